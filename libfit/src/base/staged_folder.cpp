#include "libfit/base/staged_folder.hpp"

#include <fcntl.h>
#include <stdio.h>
#include <sys/file.h>
#include <sys/stat.h>
#include <unistd.h>

#include <cerrno>
#include <fstream>
#include <iterator>
#include <system_error>
#include <vector>

#include "base/exclusive_file.hpp"
#include "libfit/base/deferred_signals.hpp"
#include "libfit/base/errors.hpp"

namespace metalfit {
namespace {

namespace fs = std::filesystem;

// An open file descriptor, closed at the end of its scope.
class Descriptor {
public:
    explicit Descriptor(int fd) : fd_(fd) {}
    ~Descriptor() {
        if (fd_ >= 0) ::close(fd_);
    }
    Descriptor(const Descriptor&) = delete;
    Descriptor& operator=(const Descriptor&) = delete;
    int get() const { return fd_; }

private:
    int fd_;
};

std::string read_whole(const fs::path& file) {
    std::ifstream in(file, std::ios::binary);
    if (!in) throw InputError({file}, "cannot read");
    return {std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>()};
}

// "gold/" and "gold/." name the folder "gold"; a link to a folder is followed (the user named that folder).
fs::path folder_named(const fs::path& requested) {
    std::error_code ec;
    fs::path dir = fs::absolute(requested, ec).lexically_normal();
    if (ec) throw InputError({requested}, "cannot resolve the folder");
    if (!dir.has_filename() && dir.has_relative_path()) dir = dir.parent_path();
    if (fs::is_symlink(dir, ec)) {
        // A link another user planted in a folder anyone can write (/tmp, /dev/shm) is not followed: it would send
        // the output (and the replacement of a folder) wherever its maker chose. The kernel's protected_symlinks rule.
        struct stat link {
        }, parent{};
        if (::lstat(dir.c_str(), &link) == 0 && ::stat(dir.parent_path().c_str(), &parent) == 0 &&
            (parent.st_mode & S_IWOTH) != 0 && link.st_uid != ::geteuid() && link.st_uid != parent.st_uid)
            throw InputError({requested}, "cannot write: a link another user made in " + dir.parent_path().string() +
                                              ", a folder anyone can write; not followed");
        dir = fs::canonical(dir, ec);
        if (ec) throw InputError({requested}, "cannot write: a link to a missing folder");
    }
    return dir;
}

bool is_same_or_inside(const fs::path& inner, const fs::path& outer) {
    auto i = inner.begin();
    for (auto o = outer.begin(); o != outer.end(); ++o, ++i)
        if (i == inner.end() || *i != *o) return false;
    return true;
}

// Creates the missing folders of `dir`, outermost first; returns those this call made.
std::vector<fs::path> create_folders(const fs::path& dir) {
    std::vector<fs::path> missing;
    std::error_code ec;
    for (fs::path p = dir; !p.empty() && !fs::exists(fs::symlink_status(p, ec)); p = p.parent_path()) {
        missing.push_back(p);
        if (p == p.parent_path()) break;
    }
    std::vector<fs::path> created;
    for (auto it = missing.rbegin(); it != missing.rend(); ++it) {
        if (::mkdir(it->c_str(), 0777) == 0) {
            created.push_back(*it);
            continue;
        }
        const int error = errno;
        if (error == EEXIST && fs::is_directory(*it, ec)) continue;  // a parallel writer made it: fine
        for (auto c = created.rbegin(); c != created.rend(); ++c) ::rmdir(c->c_str());
        throw InputError({*it}, "cannot create directory: " + detail::describe_errno(error));
    }
    if (!fs::is_directory(dir, ec)) throw InputError({dir}, "cannot write: not a directory");
    return created;
}

// Carries what `dir` holds into `staging`, below the files the caller staged: for keep_other_files.
// Old entries the caller did not write come over as hard links (copies where a link is refused), links as links;
// a file the caller wrote again is merged (`merge`) or replaced; a folder the caller wrote into that is a link (or
// a file) in the old folder is refused.
void carry_over(const fs::path& dir, const fs::path& staging, const MergeExisting& merge) {
    std::error_code ec;
    for (fs::recursive_directory_iterator it(dir, ec), end; it != end; it.increment(ec)) {
        if (ec) throw InputError({dir}, "cannot read the folder: " + ec.message());
        DeferredSignals::throw_if_pending();
        const fs::path relative = it->path().lexically_relative(dir);
        const fs::path copy = staging / relative;
        const fs::file_status old = it->symlink_status();
        std::error_code absent;  // set when nothing is staged there: not an error
        const fs::file_status mine = fs::symlink_status(copy, absent);
        const bool staged = fs::exists(mine);
        if (fs::is_symlink(old)) {
            if (staged && fs::is_directory(mine))
                throw InputError({it->path()}, "is a link; metalfit does not write into links inside its output folder "
                                               "(remove it, or choose another folder)");
            if (!staged) fs::create_symlink(fs::read_symlink(it->path()), copy, ec);  // a new file replaces it
        } else if (fs::is_directory(old)) {
            if (staged && !fs::is_directory(mine))
                throw InputError({it->path()}, "cannot write a file there: it is a directory");
            if (!staged) fs::create_directory(copy, it->path(), ec);
        } else if (fs::is_regular_file(old)) {
            if (staged && fs::is_directory(mine))
                throw InputError({it->path()}, "cannot write a folder there: it is a file");
            if (staged) {
                if (merge) {
                    const std::string merged = merge(relative, read_whole(it->path()), read_whole(copy));
                    if (::unlink(copy.c_str()) != 0)
                        throw InputError({it->path()}, "cannot replace: " + detail::describe_errno(errno));
                    if (const int error = detail::write_new_file(copy, merged); error != 0)
                        throw InputError({it->path()}, "cannot write: " + detail::describe_errno(error));
                }
            } else if (::link(it->path().c_str(), copy.c_str()) != 0) {
                const int error = detail::write_new_file(copy, read_whole(it->path()));
                if (error != 0) throw InputError({it->path()}, "cannot carry over: " + detail::describe_errno(error));
                fs::permissions(copy, old.permissions(), ec);
            }
        } else {
            throw InputError({it->path()}, "cannot carry over a special file (the folder is replaced as a unit)");
        }
        if (ec) throw InputError({it->path()}, "cannot carry over: " + ec.message());
    }
}

mode_t current_umask() {
    const mode_t mask = ::umask(022);
    ::umask(mask);
    return mask;
}

// Swaps `staging` and `dir`; afterwards `staging` names the old folder. False when the filesystem cannot exchange.
bool exchange(const fs::path& staging, const fs::path& dir) {
    if (::renameat2(AT_FDCWD, staging.c_str(), AT_FDCWD, dir.c_str(), RENAME_EXCHANGE) == 0) return true;
    if (errno == EINVAL || errno == ENOSYS || errno == EOPNOTSUPP) return false;
    throw InputError({dir}, "cannot switch the new folder in: " + detail::describe_errno(errno));
}

}  // namespace

StagedFolder::StagedFolder(const fs::path& requested, Existing existing, MergeExisting merge)
    : requested_(requested), existing_(existing), merge_(std::move(merge)) {
    dir_ = folder_named(requested);
    std::error_code ec;
    if (const fs::path cwd = fs::current_path(ec);
        !ec && is_same_or_inside(fs::weakly_canonical(cwd, ec), fs::weakly_canonical(dir_, ec)))
        throw UsageError(
            requested.string() +
            ": the output folder is the current folder or holds it; its files are "
            "replaced as one unit by switching folders, which would leave you in the old one: give a folder "
            "below the current one");
    if (!dir_.has_parent_path() || dir_ == dir_.root_path())
        throw InputError({requested}, "cannot write: not a folder name");
    const fs::path parent = dir_.parent_path();
    struct stat old {};
    if (::lstat(dir_.c_str(), &old) == 0) {
        if (!S_ISDIR(old.st_mode)) throw InputError({dir_}, "cannot write: not a directory");
        if (existing_ == Existing::keep_other_files && ::access(dir_.c_str(), W_OK) != 0)
            throw InputError({dir_}, "cannot write: directory is not writable");
    }
    created_ = create_folders(parent);
    try {
        int error = 0;
        const std::optional<fs::path> staging = detail::make_staging_folder_beside(dir_, error);
        if (!staging)
            throw InputError({dir_}, "cannot write: directory " + parent.string() + " is not writable (" +
                                         detail::describe_errno(error) +
                                         "; the new files are staged beside the folder)");
        staging_ = *staging;
        staging_fd_ = detail::lock_staging_folder(staging_);
        if (staging_fd_ < 0)
            throw InputError({dir_}, "cannot lock the staging folder: " + detail::describe_errno(errno));
    } catch (...) {
        if (staging_fd_ >= 0) ::close(staging_fd_);
        if (!staging_.empty()) ::rmdir(staging_.c_str());
        for (auto c = created_.rbegin(); c != created_.rend(); ++c) ::rmdir(c->c_str());
        throw;
    }
}

StagedFolder::~StagedFolder() {
    if (!committed_ && !staging_.empty()) {
        std::error_code ignored;
        fs::remove_all(staging_, ignored);
        for (auto c = created_.rbegin(); c != created_.rend(); ++c) ::rmdir(c->c_str());
    }
    if (staging_fd_ >= 0) ::close(staging_fd_);
}

fs::path StagedFolder::file(const fs::path& relative) {
    if (committed_) throw std::logic_error("StagedFolder: written after commit");
    DeferredSignals::throw_if_pending();
    const fs::path normal = relative.lexically_normal();
    if (relative.empty() || normal.is_absolute() || normal.empty() || *normal.begin() == ".." || normal == ".")
        throw InputError({dir_ / relative}, "cannot write: not a file inside the output folder");
    const fs::path target = staging_ / normal;
    std::error_code ec;
    fs::create_directories(target.parent_path(), ec);
    if (ec) throw InputError({(dir_ / normal).parent_path()}, "cannot create directory: " + ec.message());
    return target;
}

void StagedFolder::write(const fs::path& relative, std::string_view contents) {
    const fs::path target = file(relative);
    const fs::path shown = dir_ / relative.lexically_normal();
    std::error_code ec;
    const fs::file_status st = fs::symlink_status(target, ec);
    if (fs::is_directory(st)) throw InputError({shown}, "cannot write: it is a directory");
    if (fs::exists(st) && ::unlink(target.c_str()) != 0)
        throw InputError({shown}, "cannot replace: " + detail::describe_errno(errno));
    if (const int error = detail::write_new_file(target, contents); error != 0)
        throw InputError({shown}, "cannot write: " + detail::describe_errno(error));
}

void StagedFolder::commit() {
    if (committed_) throw std::logic_error("StagedFolder: committed twice");
    DeferredSignals::throw_if_pending();
    const fs::path parent = dir_.parent_path();
    const Descriptor parent_fd(::open(parent.c_str(), O_RDONLY | O_DIRECTORY | O_CLOEXEC));
    if (parent_fd.get() < 0) throw InputError({parent}, "cannot open the folder: " + detail::describe_errno(errno));
    while (::flock(parent_fd.get(), LOCK_EX) != 0)
        if (errno != EINTR) throw InputError({parent}, "cannot lock the folder: " + detail::describe_errno(errno));

    struct stat old {};
    const bool existed = ::lstat(dir_.c_str(), &old) == 0;
    if (existed && !S_ISDIR(old.st_mode)) throw InputError({dir_}, "cannot write: not a directory");
    if (existed && existing_ == Existing::keep_other_files) carry_over(dir_, staging_, merge_);
    const mode_t mode = existed ? (old.st_mode & 07777) : (0777 & ~current_umask());
    if (::chmod(staging_.c_str(), mode) != 0) throw InputError({dir_}, "cannot set the folder's permissions");
    if (existed && ::geteuid() == 0 && ::chown(staging_.c_str(), old.st_uid, old.st_gid) != 0) {
        // the new folder stays root's: no worse than a new export
    }
    DeferredSignals::throw_if_pending();

    if (!existed) {
        if (::rename(staging_.c_str(), dir_.c_str()) != 0)
            throw InputError({dir_}, "cannot switch the new folder in: " + detail::describe_errno(errno));
        committed_ = true;
        return;
    }
    fs::path old_folder = staging_;
    if (!exchange(staging_, dir_)) {
        // A filesystem without RENAME_EXCHANGE: two renames, the old folder first moved aside under a staging name
        // (a kill between them leaves no folder at the name, only the old one beside it: docs/development.md).
        old_folder = detail::staging_name_beside(dir_, detail::kStagingMark);
        if (::rename(dir_.c_str(), old_folder.c_str()) != 0)
            throw InputError({dir_}, "cannot switch the new folder in: " + detail::describe_errno(errno));
        if (::rename(staging_.c_str(), dir_.c_str()) != 0) {
            const int error = errno;
            ::rename(old_folder.c_str(), dir_.c_str());
            throw InputError({dir_}, "cannot switch the new folder in: " + detail::describe_errno(error));
        }
    }
    committed_ = true;
    std::error_code ignored;
    fs::remove_all(old_folder, ignored);  // the old folder; a kill here leaves it to the next writer
}

void update_folder_as_unit(const fs::path& dir, std::span<const OutputFile> files, const MergeExisting& merge) {
    StagedFolder staged(dir, StagedFolder::Existing::keep_other_files, merge);
    for (const OutputFile& f : files) staged.write(f.path, f.contents);
    staged.commit();
}

void replace_folder_as_unit(const fs::path& dir, std::span<const OutputFile> files) {
    StagedFolder staged(dir, StagedFolder::Existing::replace_folder);
    for (const OutputFile& f : files) staged.write(f.path, f.contents);
    staged.commit();
}

}  // namespace metalfit
