#include "staged_write.hpp"

#include <stdlib.h>

#include <exception>
#include <string>
#include <system_error>

#include "libfit/base/errors.hpp"

namespace metalfit::glpreview {

void write_staged(const std::filesystem::path& file, const std::function<void(const std::filesystem::path&)>& write) {
    const std::filesystem::path dir = file.has_parent_path() ? file.parent_path() : std::filesystem::path(".");
    std::string pattern = (dir / ("." + file.filename().string().substr(0, 200) + ".partial-XXXXXX")).string();
    if (::mkdtemp(pattern.data()) == nullptr)
        throw InputError(InputLocation(file), "cannot write the image: directory " + dir.string() + " is not writable");
    const std::filesystem::path staging = pattern;
    auto fail = [&](const std::string& why) {
        std::error_code ignored;
        std::filesystem::remove_all(staging, ignored);
        throw InputError(InputLocation(file), "cannot write the image: " + why);
    };
    const std::filesystem::path temporary = staging / file.filename();
    try {
        write(temporary);
    } catch (const std::exception& e) {
        fail(e.what());
    }
    std::error_code error;
    std::filesystem::rename(temporary, file, error);
    if (error) fail(error.message());
    std::filesystem::remove(staging, error);
}

}  // namespace metalfit::glpreview
