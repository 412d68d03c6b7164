#include "libfit/base/atomic_file.hpp"

#include <fcntl.h>
#include <sys/stat.h>
#include <unistd.h>

#include <iostream>
#include <system_error>
#include <vector>

#include "base/exclusive_file.hpp"
#include "libfit/base/deferred_signals.hpp"
#include "libfit/base/errors.hpp"

namespace metalfit {
namespace {

namespace fs = std::filesystem;

// What is at `target` now, without following a link there.
enum class TargetKind { none, regular, link, directory, written_in_place, refused };

// "/dev/stdout", "/dev/stderr", "/dev/fd/N", "/proc/self/fd/N", "/proc/thread-self/fd/N" (spelled plainly).
bool is_descriptor_link(const fs::path& target) {
    const std::string s = target.lexically_normal().string();
    if (s == "/dev/stdout" || s == "/dev/stderr") return true;
    for (std::string_view dir : {"/dev/fd/", "/proc/self/fd/", "/proc/thread-self/fd/"})
        if (s.starts_with(dir) && s.size() > dir.size() &&
            s.find_first_not_of("0123456789", dir.size()) == std::string::npos)
            return true;
    return false;
}

TargetKind kind_of(const fs::path& target) {
    struct stat st {};
    if (::lstat(target.c_str(), &st) != 0) return TargetKind::none;
    if (S_ISREG(st.st_mode)) return TargetKind::regular;
    if (S_ISDIR(st.st_mode)) return TargetKind::directory;
    if (S_ISLNK(st.st_mode)) {
        // /dev/stdout, /dev/stderr, /dev/fd/N, /proc/self/fd/N: the links the system keeps for this process's own
        // descriptors, written through. Any other link, under /dev/ (/dev/shm is anyone's) and /proc/ too, is
        // replaced by the renamed file, never written through (a planted link cannot redirect the output).
        return is_descriptor_link(target) ? TargetKind::written_in_place : TargetKind::link;
    }
    if (S_ISCHR(st.st_mode) || S_ISFIFO(st.st_mode) || S_ISSOCK(st.st_mode)) return TargetKind::written_in_place;
    return TargetKind::refused;  // block devices
}

void write_in_place(const fs::path& target, std::string_view contents) {
    const int fd = ::open(target.c_str(), O_WRONLY | O_TRUNC | O_NOCTTY | O_CLOEXEC);
    if (fd < 0) throw InputError({target}, "cannot write: " + detail::describe_errno(errno));
    int error = detail::write_all(fd, contents) ? 0 : errno;
    if (::close(fd) != 0 && error == 0) error = errno;
    if (error != 0) throw InputError({target}, "cannot write: " + detail::describe_errno(error));
}

[[noreturn]] void throw_cannot_write(const fs::path& target, int error) {
    if (error == EACCES || error == EPERM || error == EROFS)
        throw InputError({target},
                         "cannot write: directory " + detail::directory_of(target).string() + " is not writable");
    throw InputError({target}, "cannot write: " + detail::describe_errno(error));
}

void check_target(const fs::path& target, TargetKind kind) {
    if (kind == TargetKind::directory) throw InputError({target}, "cannot write: it is a directory");
    if (kind == TargetKind::refused) throw InputError({target}, "cannot write: it exists and is not a regular file");
    std::error_code ec;
    if (!fs::is_directory(detail::directory_of(target), ec))
        throw InputError({target},
                         "cannot write: directory " + detail::directory_of(target).string() + " does not exist");
}

}  // namespace

void write_file_atomically(const fs::path& target, std::string_view contents) {
    const TargetKind kind = kind_of(target);
    // A device, FIFO or terminal (-o /dev/null, -o /dev/stdout) is written in place: renaming a regular file over it
    // would replace the device itself.
    if (kind == TargetKind::written_in_place) return write_in_place(target, contents);
    check_target(target, kind);
    const DeferredSignals deferred;
    int error = 0;
    const auto temporary = detail::write_temporary_beside(target, contents, error);
    if (!temporary) throw_cannot_write(target, error);
    if (DeferredSignals::pending() || ::rename(temporary->c_str(), target.c_str()) != 0) {
        error = errno;
        ::unlink(temporary->c_str());
        DeferredSignals::throw_if_pending();
        throw InputError({target}, "cannot rename temporary file into place: " + detail::describe_errno(error));
    }
}

void write_files_atomically(std::span<const OutputFile> files) {
    const DeferredSignals deferred;
    std::vector<fs::path> temporaries;
    const auto remove_temporaries = [&](std::size_t from) {
        for (std::size_t j = from; j < temporaries.size(); ++j) ::unlink(temporaries[j].c_str());
    };
    for (const OutputFile& f : files) {
        const TargetKind kind = kind_of(f.path);
        try {
            if (kind == TargetKind::written_in_place)
                throw InputError({f.path}, "cannot write: it exists and is not a regular file");
            check_target(f.path, kind);
            DeferredSignals::throw_if_pending();
            int error = 0;
            const auto temporary = detail::write_temporary_beside(f.path, f.contents, error);
            if (!temporary) throw_cannot_write(f.path, error);
            temporaries.push_back(*temporary);
        } catch (...) {
            remove_temporaries(0);
            throw;
        }
    }
    std::vector<fs::path> renamed_new;  // targets that did not exist before
    for (std::size_t i = 0; i < files.size(); ++i) {
        const bool existed = kind_of(files[i].path) != TargetKind::none;
        if (DeferredSignals::pending() || ::rename(temporaries[i].c_str(), files[i].path.c_str()) != 0) {
            const int error = errno;
            remove_temporaries(i);
            for (const fs::path& p : renamed_new) ::unlink(p.c_str());
            DeferredSignals::throw_if_pending();
            throw InputError({files[i].path},
                             "cannot rename temporary file into place: " + detail::describe_errno(error));
        }
        if (!existed) renamed_new.push_back(files[i].path);
    }
}

StreamedOutputFile::StreamedOutputFile(const fs::path& target) : target_(target) {
    const TargetKind kind = kind_of(target);
    if (kind == TargetKind::written_in_place) {
        spool_ = std::tmpfile();
        if (!spool_) throw InputError({target}, "cannot write: no temporary file: " + detail::describe_errno(errno));
        return;
    }
    check_target(target, kind);
    deferred_.emplace();
    int error = 0;
    const auto temporary = detail::open_temporary_beside(target, error);
    if (!temporary) {
        deferred_.reset();
        throw_cannot_write(target, error);
    }
    temporary_ = temporary->path;
    fd_ = temporary->fd;
}

StreamedOutputFile::StreamedOutputFile(StandardOutput) : spool_(std::tmpfile()) {
    if (!spool_)
        throw InputError({fs::path("<stdout>")}, "cannot write: no temporary file: " + detail::describe_errno(errno));
}

StreamedOutputFile::~StreamedOutputFile() {
    if (fd_ >= 0) ::close(fd_);
    if (!temporary_.empty() && !committed_) ::unlink(temporary_.c_str());
    if (spool_) std::fclose(spool_);
}

void StreamedOutputFile::write(std::string_view text) {
    if (committed_) throw std::logic_error("StreamedOutputFile: written after commit");
    if (spool_) {
        if (std::fwrite(text.data(), 1, text.size(), spool_) != text.size())
            throw InputError({target_.empty() ? fs::path("<stdout>") : target_},
                             "cannot write: temporary file: " + detail::describe_errno(errno));
        return;
    }
    DeferredSignals::throw_if_pending();
    if (!detail::write_all(fd_, text)) throw InputError({target_}, "cannot write: " + detail::describe_errno(errno));
}

void StreamedOutputFile::commit() {
    if (committed_) throw std::logic_error("StreamedOutputFile: committed twice");
    if (spool_) {
        // The anonymous temporary, copied out: to standard output through std::cout (its other text stays in order), or
        // to the device in place.
        if (std::fflush(spool_) != 0 || std::fseek(spool_, 0, SEEK_SET) != 0)
            throw InputError({target_.empty() ? fs::path("<stdout>") : target_},
                             "cannot write: temporary file: " + detail::describe_errno(errno));
        int fd = -1;
        if (!target_.empty()) {
            fd = ::open(target_.c_str(), O_WRONLY | O_TRUNC | O_NOCTTY | O_CLOEXEC);
            if (fd < 0) throw InputError({target_}, "cannot write: " + detail::describe_errno(errno));
        }
        char buffer[1 << 16];
        int error = 0;
        for (std::size_t n; (n = std::fread(buffer, 1, sizeof buffer, spool_)) > 0;) {
            if (fd < 0)
                std::cout.write(buffer, static_cast<std::streamsize>(n));
            else if (!detail::write_all(fd, {buffer, n})) {
                error = errno;
                break;
            }
        }
        if (std::ferror(spool_) && error == 0) error = errno ? errno : EIO;
        if (fd < 0)
            std::cout.flush();
        else if (::close(fd) != 0 && error == 0)
            error = errno;
        committed_ = true;
        if (error != 0)
            throw InputError({target_.empty() ? fs::path("<stdout>") : target_},
                             "cannot write: " + detail::describe_errno(error));
        return;
    }
    const int fd = fd_;
    fd_ = -1;
    if (::close(fd) != 0) throw InputError({target_}, "cannot write: " + detail::describe_errno(errno));
    if (DeferredSignals::pending() || ::rename(temporary_.c_str(), target_.c_str()) != 0) {
        const int error = errno;
        DeferredSignals::throw_if_pending();  // the destructor removes the temporary
        throw InputError({target_}, "cannot rename temporary file into place: " + detail::describe_errno(error));
    }
    committed_ = true;
}

}  // namespace metalfit
