#include "oiio_module.hpp"

#include <dlfcn.h>

#include <algorithm>
#include <filesystem>
#include <mutex>
#include <stdexcept>
#include <system_error>
#include <vector>

namespace metalfit::glpreview {
namespace {

constexpr const char* kModuleFile = METALFIT_OIIO_MODULE_FILE;

std::filesystem::path executable_dir() {
    std::error_code error;
    const std::filesystem::path exe = std::filesystem::read_symlink("/proc/self/exe", error);
    return error ? std::filesystem::path() : exe.parent_path();
}

const OiioModuleApi* load() {
    std::string tried;
    const std::filesystem::path beside = executable_dir();
    std::vector<std::filesystem::path> dirs;
    if (!beside.empty()) dirs = {beside, (beside / METALFIT_OIIO_MODULE_RELATIVE_DIR).lexically_normal()};
    if (std::find(dirs.begin(), dirs.end(), METALFIT_OIIO_MODULE_INSTALL_DIR) == dirs.end())
        dirs.emplace_back(METALFIT_OIIO_MODULE_INSTALL_DIR);
    for (const std::filesystem::path& dir : dirs) {
        const std::filesystem::path file = dir / kModuleFile;
        std::error_code error;
        if (!std::filesystem::exists(file, error)) {
            tried += (tried.empty() ? "" : ", ") + file.string();
            continue;
        }
        // RTLD_LOCAL: OpenImageIO's symbols stay the module's own.
        void* handle = ::dlopen(file.c_str(), RTLD_NOW | RTLD_LOCAL);
        if (handle == nullptr)
            throw std::runtime_error(std::string("cannot load the OpenImageIO module: ") + ::dlerror());
        using Entry = const OiioModuleApi* (*)();
        const auto entry = reinterpret_cast<Entry>(::dlsym(handle, kOiioModuleEntry));
        const OiioModuleApi* api = entry ? entry() : nullptr;
        if (api == nullptr || api->version != OiioModuleApi::kVersion || !api->read_rgb || !api->draw_text)
            throw std::runtime_error("the OpenImageIO module " + file.string() +
                                     " is not this glpreview's (rebuild or reinstall)");
        return api;
    }
    throw std::runtime_error(std::string("the OpenImageIO module (") + kModuleFile +
                             ", for images other than EXR and for the "
                             "sheet's labels) is missing: looked for " +
                             tried + " (rebuild or reinstall glpreview)");
}

}  // namespace

const OiioModuleApi& oiio_module() {
    static std::mutex mutex;
    static const OiioModuleApi* api = nullptr;
    const std::lock_guard lock(mutex);
    if (api == nullptr) api = load();  // a failure throws, and the next call tries again
    return *api;
}

}  // namespace metalfit::glpreview
