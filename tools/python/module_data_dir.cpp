#include "module_data_dir.hpp"

#include <dlfcn.h>

#include <cstdlib>
#include <system_error>

#include "libfit/base/data_dir.hpp"

namespace metalfit::python {

std::filesystem::path module_data_dir() {
    if (const char* env = std::getenv("METALFIT_DATA"); env && *env) return env;
    // The module's own file, found from the address of this function (dladdr names the shared object holding it).
    Dl_info info{};
    if (dladdr(reinterpret_cast<void*>(&module_data_dir), &info) != 0 && info.dli_fname) {
        std::error_code error;
        const std::filesystem::path installed =
            std::filesystem::path(info.dli_fname).parent_path() / METALFIT_PYTHON_TO_DATA;
        if (std::filesystem::is_directory(installed, error)) return installed.lexically_normal();
    }
    return default_data_dir();
}

}  // namespace metalfit::python
