#include "libfit/atomic_file.hpp"

#include <unistd.h>

#include <cstdio>
#include <fstream>
#include <system_error>

#include "libfit/errors.hpp"

namespace metalfit {

void write_file_atomically(const std::filesystem::path& target, std::string_view contents) {
    namespace fs = std::filesystem;
    const fs::path dir = target.has_parent_path() ? target.parent_path() : fs::path(".");
    std::error_code ec;
    // A device, FIFO or terminal (-o /dev/null, -o /dev/stdout) is written in place: renaming a regular file over it
    // would replace the device itself.
    if (fs::exists(target, ec) && !fs::is_regular_file(target, ec)) {
        if (fs::is_directory(target, ec)) throw InputError({target}, "cannot write: it is a directory");
        std::ofstream out(target, std::ios::binary);
        out.write(contents.data(), static_cast<std::streamsize>(contents.size()));
        out.flush();
        if (!out) throw InputError({target}, "cannot write");
        return;
    }
    if (!fs::is_directory(dir, ec))
        throw InputError({target}, "cannot write: directory " + dir.string() + " does not exist");
    std::string temporary_name = ".";
    temporary_name += target.filename().string();
    temporary_name += ".tmp.";
    temporary_name += std::to_string(::getpid());
    const fs::path temporary = dir / temporary_name;
    {
        std::ofstream out(temporary, std::ios::binary | std::ios::trunc);
        if (!out) throw InputError({target}, "cannot write: directory " + dir.string() + " is not writable");
        out.write(contents.data(), static_cast<std::streamsize>(contents.size()));
        out.flush();
        if (!out) {
            out.close();
            fs::remove(temporary, ec);
            throw InputError({target}, "cannot write (disk full?)");
        }
    }
    fs::rename(temporary, target, ec);
    if (ec) {
        fs::remove(temporary, ec);
        throw InputError({target}, "cannot rename temporary file into place");
    }
}

}  // namespace metalfit
