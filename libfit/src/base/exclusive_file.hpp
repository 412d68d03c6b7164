// Internal: files created exclusively under unpredictable names (atomic_file, staged_folder).
#pragma once

#include <fcntl.h>
#include <sys/random.h>
#include <unistd.h>

#include <cerrno>
#include <cstring>
#include <filesystem>
#include <optional>
#include <string>
#include <string_view>

#include "libfit/base/errors.hpp"

namespace metalfit::detail {

// 16 hex digits from the kernel's random source: a name another user cannot guess before it exists.
inline std::string unpredictable_suffix() {
    unsigned char bytes[8] = {};
    std::size_t got = 0;
    while (got < sizeof bytes) {
        const ssize_t n = ::getrandom(bytes + got, sizeof bytes - got, 0);
        if (n < 0 && errno == EINTR) continue;
        if (n <= 0) throw std::runtime_error("getrandom failed");
        got += static_cast<std::size_t>(n);
    }
    static constexpr char kHex[] = "0123456789abcdef";
    std::string s;
    for (unsigned char b : bytes) {
        s += kHex[b >> 4];
        s += kHex[b & 15];
    }
    return s;
}

// Writes all of `contents` to `fd`; false on an error (errno set).
inline bool write_all(int fd, std::string_view contents) {
    while (!contents.empty()) {
        const ssize_t n = ::write(fd, contents.data(), contents.size());
        if (n < 0 && errno == EINTR) continue;
        if (n <= 0) return false;
        contents.remove_prefix(static_cast<std::size_t>(n));
    }
    return true;
}

// Creates `path`, which must not exist (O_CREAT | O_EXCL | O_NOFOLLOW: never a file a link points to), writes
// `contents` and closes it. Returns the errno of the first failure, or 0. A failed file is removed.
inline int write_new_file(const std::filesystem::path& path, std::string_view contents) {
    const int fd = ::open(path.c_str(), O_WRONLY | O_CREAT | O_EXCL | O_NOFOLLOW | O_CLOEXEC, 0666);
    if (fd < 0) return errno;
    int error = write_all(fd, contents) ? 0 : errno;
    if (::close(fd) != 0 && error == 0) error = errno;
    if (error != 0) ::unlink(path.c_str());
    return error;
}

// The name of a temporary beside `target`: ".<target name>.<random>.tmp" in the same directory.
inline std::filesystem::path temporary_name_beside(const std::filesystem::path& target) {
    const std::filesystem::path dir = target.has_parent_path() ? target.parent_path() : std::filesystem::path(".");
    return dir / ("." + target.filename().string().substr(0, 200) + "." + unpredictable_suffix() + ".tmp");
}

// A new file beside `target` named ".<target name>.<random>.tmp" holding `contents`; the path on success, else
// nullopt with `error` set (EEXIST is retried with another name).
inline std::optional<std::filesystem::path> write_temporary_beside(const std::filesystem::path& target,
                                                                   std::string_view contents, int& error) {
    for (int attempt = 0; attempt < 16; ++attempt) {
        const std::filesystem::path temporary = temporary_name_beside(target);
        error = write_new_file(temporary, contents);
        if (error == 0) return temporary;
        if (error != EEXIST) return std::nullopt;
    }
    return std::nullopt;
}

// An empty temporary beside `target`, created as write_new_file creates its files and left open for writing: its
// path and descriptor, else nullopt with `error` set (EEXIST is retried with another name).
struct OpenTemporary {
    std::filesystem::path path;
    int fd = -1;
};
inline std::optional<OpenTemporary> open_temporary_beside(const std::filesystem::path& target, int& error) {
    for (int attempt = 0; attempt < 16; ++attempt) {
        const std::filesystem::path temporary = temporary_name_beside(target);
        const int fd = ::open(temporary.c_str(), O_WRONLY | O_CREAT | O_EXCL | O_NOFOLLOW | O_CLOEXEC, 0666);
        if (fd >= 0) {
            error = 0;
            return OpenTemporary{temporary, fd};
        }
        error = errno;
        if (error != EEXIST) return std::nullopt;
    }
    return std::nullopt;
}

// "disk full" for ENOSPC, the system's words otherwise.
inline std::string describe_errno(int error) {
    if (error == ENOSPC || error == EDQUOT) return "disk full";
    return std::strerror(error);
}

}  // namespace metalfit::detail
