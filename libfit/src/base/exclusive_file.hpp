// Internal: files created exclusively under unpredictable names, and the staging names that killed writers leave
// (atomic_file, staged_folder).
#pragma once

#include <fcntl.h>
#include <signal.h>
#include <sys/file.h>
#include <sys/random.h>
#include <sys/stat.h>
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

// Staging names: "." + the target's name (cut at 200 bytes) + a mark + "<pid>.<16 hex digits>". The pid and the
// lock the writer holds on its staging while it lives (lock_staging) are what make a name provably a writer's own:
// the next writer removes one only when all of these hold (owner_is_gone): the exact pattern, owned by this user, not
// a link, of the expected kind, its pid not running, and its lock free. A user's file that merely starts the same
// way is never touched.
inline constexpr std::string_view kTemporaryMark = ".metalfit-tmp.";
inline constexpr std::string_view kStagingMark = ".metalfit-staging.";

inline std::string staging_prefix(const std::filesystem::path& target, std::string_view mark) {
    return "." + target.filename().string().substr(0, 200) + std::string(mark);
}

inline std::filesystem::path directory_of(const std::filesystem::path& target) {
    return target.has_parent_path() ? target.parent_path() : std::filesystem::path(".");
}

// A fresh staging name beside `target`: prefix + pid + "." + random.
inline std::filesystem::path staging_name_beside(const std::filesystem::path& target, std::string_view mark) {
    return directory_of(target) /
           (staging_prefix(target, mark) + std::to_string(::getpid()) + "." + unpredictable_suffix());
}

// The pid of a staging name after its prefix ("<pid>.<16 hex>"), or 0 when the rest is not exactly that.
inline pid_t staging_pid(std::string_view rest) {
    const std::size_t dot = rest.find('.');
    if (dot == std::string_view::npos || dot == 0 || dot > 9 || rest.size() != dot + 17) return 0;
    long pid = 0;
    for (char c : rest.substr(0, dot)) {
        if (c < '0' || c > '9') return 0;
        pid = pid * 10 + (c - '0');
    }
    for (char c : rest.substr(dot + 1))
        if (!((c >= '0' && c <= '9') || (c >= 'a' && c <= 'f'))) return 0;
    return pid > 0 ? static_cast<pid_t>(pid) : 0;
}

// Takes the writer's lock on a staging file or folder, held until `fd` is closed: an open-file-description read lock
// (fcntl F_OFD_SETLKW), which never conflicts with the flock that serialises the commits into a folder — a writer
// whose output folder lies inside another writer's staging (the report's glpreview renders) cannot deadlock on it.
// `fd` must be open for reading.
inline bool lock_staging(int fd) {
    struct flock lock {};
    lock.l_type = F_RDLCK;
    lock.l_whence = SEEK_SET;
    while (::fcntl(fd, F_OFD_SETLKW, &lock) != 0)
        if (errno != EINTR) return false;
    return true;
}

// True when nobody holds lock_staging's lock on `fd`.
inline bool staging_lock_is_free(int fd) {
    struct flock probe {};
    probe.l_type = F_WRLCK;
    probe.l_whence = SEEK_SET;
    return ::fcntl(fd, F_OFD_GETLK, &probe) == 0 && probe.l_type == F_UNLCK;
}

// True when `path` (whose name is prefix + `rest`) was staged by a metalfit writer that is gone (see above).
inline bool owner_is_gone(const std::filesystem::path& path, std::string_view rest, bool directory) {
    const pid_t pid = staging_pid(rest);
    if (pid == 0) return false;
    if (pid == ::getpid() || ::kill(pid, 0) == 0 || errno != ESRCH) return false;  // running (or not ours to probe)
    struct stat st {};
    if (::lstat(path.c_str(), &st) != 0 || st.st_uid != ::geteuid()) return false;
    if (directory ? !S_ISDIR(st.st_mode) : !S_ISREG(st.st_mode)) return false;
    const int fd =
        ::open(path.c_str(), (directory ? O_RDONLY | O_DIRECTORY : O_RDONLY) | O_NOFOLLOW | O_CLOEXEC | O_NONBLOCK);
    if (fd < 0) return false;
    const bool free = staging_lock_is_free(fd);
    ::close(fd);
    return free;
}

// Removes what killed writers left beside `target` under `mark` (files for kTemporaryMark, folders for kStagingMark).
inline void remove_stale_beside(const std::filesystem::path& target, std::string_view mark) {
    const std::string prefix = staging_prefix(target, mark);
    const bool directory = mark == kStagingMark;
    std::error_code ec;
    for (std::filesystem::directory_iterator it(directory_of(target), ec), end; !ec && it != end; it.increment(ec)) {
        const std::string name = it->path().filename().string();
        if (!name.starts_with(prefix) ||
            !owner_is_gone(it->path(), std::string_view(name).substr(prefix.size()), directory))
            continue;
        std::error_code ignored;
        if (directory)
            std::filesystem::remove_all(it->path(), ignored);
        else
            ::unlink(it->path().c_str());
    }
}

// A new staging folder beside `target` (mode 0700, named by staging_name_beside(kStagingMark), made exclusively;
// EEXIST is retried with another name), after the staging folders that killed writers left there were removed: its
// path, else nullopt with `error` set. The caller locks it (lock_staging_folder) for as long as it writes there.
inline std::optional<std::filesystem::path> make_staging_folder_beside(const std::filesystem::path& target,
                                                                       int& error) {
    remove_stale_beside(target, kStagingMark);
    error = 0;
    for (int attempt = 0; attempt < 16; ++attempt) {
        const std::filesystem::path name = staging_name_beside(target, kStagingMark);
        if (::mkdir(name.c_str(), 0700) == 0) return name;
        if ((error = errno) != EEXIST) return std::nullopt;
    }
    return std::nullopt;
}

// Opens the staging folder `path` and takes lock_staging's lock on it: the descriptor that holds the lock (close it
// to release), or -1 with errno set.
inline int lock_staging_folder(const std::filesystem::path& path) {
    const int fd = ::open(path.c_str(), O_RDONLY | O_DIRECTORY | O_NOFOLLOW | O_CLOEXEC);
    if (fd < 0) return -1;
    if (!lock_staging(fd)) {
        const int error = errno;
        ::close(fd);
        errno = error;
        return -1;
    }
    return fd;
}

// An empty temporary beside `target`, named by staging_name_beside(kTemporaryMark), created exclusively (never
// through a link) and left open (and locked: lock_staging) for writing: its path and descriptor, else nullopt with
// `error` set (EEXIST is retried with another name). Temporaries that killed writers left are removed first.
struct OpenTemporary {
    std::filesystem::path path;
    int fd = -1;
};
inline std::optional<OpenTemporary> open_temporary_beside(const std::filesystem::path& target, int& error) {
    remove_stale_beside(target, kTemporaryMark);
    for (int attempt = 0; attempt < 16; ++attempt) {
        const std::filesystem::path temporary = staging_name_beside(target, kTemporaryMark);
        const int fd = ::open(temporary.c_str(), O_RDWR | O_CREAT | O_EXCL | O_NOFOLLOW | O_CLOEXEC, 0666);
        if (fd >= 0) {
            lock_staging(fd);
            error = 0;
            return OpenTemporary{temporary, fd};
        }
        error = errno;
        if (error != EEXIST) return std::nullopt;
    }
    return std::nullopt;
}

// A new temporary beside `target` (open_temporary_beside) holding `contents`, locked while written and closed: its
// path on success, else nullopt with `error` set (nothing left behind).
inline std::optional<std::filesystem::path> write_temporary_beside(const std::filesystem::path& target,
                                                                   std::string_view contents, int& error) {
    const std::optional<OpenTemporary> temporary = open_temporary_beside(target, error);
    if (!temporary) return std::nullopt;
    error = write_all(temporary->fd, contents) ? 0 : errno;
    if (::close(temporary->fd) != 0 && error == 0) error = errno;
    if (error == 0) return temporary->path;
    ::unlink(temporary->path.c_str());
    return std::nullopt;
}

// "disk full" for ENOSPC, the system's words otherwise.
inline std::string describe_errno(int error) {
    if (error == ENOSPC || error == EDQUOT) return "disk full";
    return std::strerror(error);
}

}  // namespace metalfit::detail
