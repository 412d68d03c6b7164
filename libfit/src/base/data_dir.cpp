#include "libfit/base/data_dir.hpp"

#include <cstdlib>
#include <system_error>

namespace metalfit {

std::filesystem::path default_data_dir() {
    if (const char* env = std::getenv("METALFIT_DATA"); env != nullptr && *env != '\0') return env;
    // An install: <prefix>/bin/<executable> next to <prefix>/share/metalfit, wherever the prefix was moved.
    std::error_code error;
    const std::filesystem::path executable = std::filesystem::read_symlink("/proc/self/exe", error);
    if (!error) {
        const std::filesystem::path installed =
            (executable.parent_path() / METALFIT_DATA_FROM_BINDIR).lexically_normal();
        if (std::filesystem::is_directory(installed, error)) return installed;
    }
    return METALFIT_DATA_DIR;
}

}  // namespace metalfit
