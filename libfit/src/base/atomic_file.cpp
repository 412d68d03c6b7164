#include "libfit/base/atomic_file.hpp"

#include <unistd.h>

#include <cstdio>
#include <fstream>
#include <system_error>
#include <vector>

#include "libfit/base/errors.hpp"

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

namespace metalfit {

void write_files_atomically(std::span<const OutputFile> files) {
    namespace fs = std::filesystem;
    std::error_code ec;
    std::vector<fs::path> temporaries;
    const auto remove_temporaries = [&] {
        for (const fs::path& t : temporaries) fs::remove(t, ec);
    };
    for (const OutputFile& f : files) {
        if (fs::exists(f.path, ec) && !fs::is_regular_file(f.path, ec))
            throw InputError({f.path}, "cannot write: it exists and is not a regular file");
        const fs::path dir = f.path.has_parent_path() ? f.path.parent_path() : fs::path(".");
        const fs::path temporary = dir / ("." + f.path.filename().string() + ".tmp." + std::to_string(::getpid()));
        std::ofstream out(temporary, std::ios::binary | std::ios::trunc);
        if (!out) {
            remove_temporaries();
            throw InputError({f.path}, "cannot write: directory " + dir.string() + " is not writable");
        }
        temporaries.push_back(temporary);
        out.write(f.contents.data(), static_cast<std::streamsize>(f.contents.size()));
        out.flush();
        if (!out) {
            remove_temporaries();
            throw InputError({f.path}, "cannot write (disk full?)");
        }
    }
    std::vector<fs::path> renamed_new;  // targets that did not exist before
    for (std::size_t i = 0; i < files.size(); ++i) {
        const bool existed = fs::exists(files[i].path, ec);
        fs::rename(temporaries[i], files[i].path, ec);
        if (ec) {
            for (std::size_t j = i; j < temporaries.size(); ++j) fs::remove(temporaries[j], ec);
            for (const fs::path& p : renamed_new) fs::remove(p, ec);
            throw InputError({files[i].path}, "cannot rename temporary file into place");
        }
        if (!existed) renamed_new.push_back(files[i].path);
    }
}

}  // namespace metalfit
