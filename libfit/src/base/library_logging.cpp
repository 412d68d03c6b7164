#include "libfit/base/library_logging.hpp"

#include <OpenColorIO/OpenColorIO.h>
#include <glog/logging.h>

#include <iostream>
#include <string>
#include <string_view>

#include "libfit/base/errors.hpp"

namespace metalfit {

void route_library_logging(const char* program) {
    // Ceres logs through glog: only FATAL (which aborts anyway) would still print. Nothing is initialised, so glog's
    // "Logging before InitGoogleLogging()" line never appears either.
    FLAGS_minloglevel = google::GLOG_FATAL;
    FLAGS_logtostderr = false;
    OCIO_NAMESPACE::SetLoggingFunction([program](const char* text) {
        std::string_view message(text);
        for (std::string_view prefix :
             {"[OpenColorIO Warning]: ", "[OpenColorIO Error]: ", "[OpenColorIO Info]: ", "[OpenColorIO Debug]: "})
            if (message.starts_with(prefix)) message.remove_prefix(prefix.size());
        while (!message.empty() && (message.back() == '\n' || message.back() == ' ')) message.remove_suffix(1);
        if (!message.empty()) std::cerr << program << ": warning: OCIO: " << sanitised_message(message) << "\n";
    });
}

}  // namespace metalfit
