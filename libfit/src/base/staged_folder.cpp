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

constexpr std::string_view kStagingMark = ".metalfit-staging.";

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

void remove_stale_staging(const fs::path& parent, const std::string& prefix) {
    std::error_code ec;
    for (fs::directory_iterator it(parent, ec), end; !ec && it != end; it.increment(ec))
        if (it->path().filename().string().starts_with(prefix)) {
            std::error_code ignored;
            fs::remove_all(it->path(), ignored);
        }
}

// Hard links (or copies) of everything in `from` below `to`, links recreated as links.
void carry_over(const fs::path& from, const fs::path& to) {
    std::error_code ec;
    for (fs::recursive_directory_iterator it(from, ec), end; it != end; it.increment(ec)) {
        if (ec) throw InputError({from}, "cannot read the folder: " + ec.message());
        DeferredSignals::throw_if_pending();
        const fs::path relative = it->path().lexically_relative(from);
        const fs::path copy = to / relative;
        const fs::file_status st = it->symlink_status();
        if (fs::is_symlink(st)) {
            fs::create_symlink(fs::read_symlink(it->path()), copy, ec);
        } else if (fs::is_directory(st)) {
            fs::create_directory(copy, it->path(), ec);
        } else if (fs::is_regular_file(st)) {
            if (::link(it->path().c_str(), copy.c_str()) != 0) {
                const int error = detail::write_new_file(copy, read_whole(it->path()));
                if (error != 0) throw InputError({it->path()}, "cannot carry over: " + detail::describe_errno(error));
                fs::permissions(copy, st.permissions(), ec);
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

void update_folder_as_unit(const fs::path& requested, std::span<const OutputFile> files, const MergeExisting& merge) {
    const fs::path dir = folder_named(requested);
    std::error_code ec;
    if (const fs::path cwd = fs::current_path(ec); !ec && is_same_or_inside(fs::weakly_canonical(cwd, ec), fs::weakly_canonical(dir, ec)))
        throw UsageError(requested.string() + ": the output folder is the current folder or holds it; its files are "
                         "replaced as one unit by switching folders, which would leave you in the old one: give a folder "
                         "below the current one");
    if (!dir.has_parent_path() || dir == dir.root_path()) throw InputError({requested}, "cannot write: not a folder name");
    const fs::path parent = dir.parent_path();
    const std::string prefix = "." + dir.filename().string() + std::string(kStagingMark);
    const std::vector<fs::path> created = create_folders(parent);
    fs::path staging;
    const auto undo = [&] {
        std::error_code ignored;
        if (!staging.empty()) fs::remove_all(staging, ignored);
        for (auto c = created.rbegin(); c != created.rend(); ++c) ::rmdir(c->c_str());
    };
    const DeferredSignals deferred;
    try {
        const Descriptor parent_fd(::open(parent.c_str(), O_RDONLY | O_DIRECTORY | O_CLOEXEC));
        if (parent_fd.get() < 0) throw InputError({parent}, "cannot open the folder: " + detail::describe_errno(errno));
        while (::flock(parent_fd.get(), LOCK_EX) != 0)
            if (errno != EINTR) throw InputError({parent}, "cannot lock the folder: " + detail::describe_errno(errno));
        remove_stale_staging(parent, prefix);

        struct stat old {};
        const bool existed = ::lstat(dir.c_str(), &old) == 0;
        if (existed && !S_ISDIR(old.st_mode)) throw InputError({dir}, "cannot write: not a directory");
        if (existed && ::access(dir.c_str(), W_OK) != 0) throw InputError({dir}, "cannot write: directory is not writable");

        std::string pattern = (parent / (prefix + "XXXXXX")).string();
        if (::mkdtemp(pattern.data()) == nullptr)
            throw InputError({dir}, "cannot write: directory " + parent.string() + " is not writable (" +
                                        detail::describe_errno(errno) + "; the new files are staged beside the folder)");
        staging = pattern;
        if (existed) carry_over(dir, staging);

        for (const OutputFile& f : files) {
            DeferredSignals::throw_if_pending();
            const fs::path target = staging / f.path;
            const fs::path shown = dir / f.path;
            fs::create_directories(target.parent_path(), ec);
            if (ec) throw InputError({shown.parent_path()}, "cannot create directory: " + ec.message());
            std::string merged;
            const std::string* contents = &f.contents;
            const fs::file_status st = fs::symlink_status(target, ec);
            if (fs::is_directory(st)) throw InputError({shown}, "cannot write: it is a directory");
            if (fs::exists(st)) {
                if (merge && fs::is_regular_file(st)) {
                    merged = merge(f.path, read_whole(target), f.contents);
                    contents = &merged;
                }
                if (::unlink(target.c_str()) != 0)
                    throw InputError({shown}, "cannot replace: " + detail::describe_errno(errno));
            }
            if (const int error = detail::write_new_file(target, *contents); error != 0)
                throw InputError({shown}, "cannot write: " + detail::describe_errno(error));
        }
        const mode_t mode = existed ? (old.st_mode & 07777) : (0777 & ~current_umask());
        if (::chmod(staging.c_str(), mode) != 0) throw InputError({dir}, "cannot set the folder's permissions");
        if (existed && ::geteuid() == 0 && ::chown(staging.c_str(), old.st_uid, old.st_gid) != 0) {
            // the new folder stays root's: no worse than a new export
        }
        DeferredSignals::throw_if_pending();

        if (!existed) {
            if (::rename(staging.c_str(), dir.c_str()) != 0)
                throw InputError({dir}, "cannot switch the new folder in: " + detail::describe_errno(errno));
            staging.clear();
            return;
        }
        if (!exchange(staging, dir)) {
            // A filesystem without RENAME_EXCHANGE: two renames, the old folder first moved aside.
            const fs::path aside = parent / (prefix + "old-" + detail::unpredictable_suffix());
            if (::rename(dir.c_str(), aside.c_str()) != 0)
                throw InputError({dir}, "cannot switch the new folder in: " + detail::describe_errno(errno));
            if (::rename(staging.c_str(), dir.c_str()) != 0) {
                const int error = errno;
                ::rename(aside.c_str(), dir.c_str());
                throw InputError({dir}, "cannot switch the new folder in: " + detail::describe_errno(error));
            }
            staging = aside;
        }
        fs::remove_all(staging, ec);  // the old folder
        staging.clear();
    } catch (...) {
        undo();
        throw;
    }
}

}  // namespace metalfit
