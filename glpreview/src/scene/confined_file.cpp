#include "glpreview/scene/confined_file.hpp"

#include <fcntl.h>
#include <sys/stat.h>
#include <unistd.h>

#include <cerrno>
#include <cstring>
#include <vector>

#include "libfit/base/errors.hpp"

namespace metalfit::glpreview {
namespace {

namespace fs = std::filesystem;

// The file the descriptor holds, as the kernel names it (every link resolved when it was opened).
fs::path opened_path(int fd) {
    std::vector<char> buffer(4096);
    const std::string link = "/proc/self/fd/" + std::to_string(fd);
    const ssize_t n = ::readlink(link.c_str(), buffer.data(), buffer.size() - 1);
    if (n <= 0) return {};
    return fs::path(std::string(buffer.data(), static_cast<std::size_t>(n)));
}

}  // namespace

ConfinedFile ConfinedFile::open(const fs::path& scene_file, const std::optional<PathPolicy>& policy,
                                const fs::path& file, const std::string& field) {
    const fs::path original = file.is_absolute() ? file : scene_file.parent_path() / file;
    const auto problem = [&](const std::string& why) {
        return InputError(InputLocation(scene_file, 0, field), original.string() + ": " + why);
    };
    // O_NONBLOCK: opening a FIFO does not wait for a writer (it is refused below); regular files ignore it.
    const int fd = ::open(original.c_str(), O_RDONLY | O_CLOEXEC | O_NONBLOCK | O_NOCTTY);
    if (fd < 0) throw problem(std::string("cannot open it: ") + std::strerror(errno));
    struct stat st {};
    if (::fstat(fd, &st) != 0 || !S_ISREG(st.st_mode)) {
        ::close(fd);
        throw problem("not a regular file");
    }
    const std::string descriptor = "/proc/self/fd/" + std::to_string(fd);
    const bool have_proc =
        ::access(descriptor.c_str(), R_OK) == 0;  // without /proc: the path, checked as it resolves now
    if (policy && !policy->allow_outside) {
        std::error_code error;
        const fs::path opened = have_proc ? opened_path(fd) : fs::weakly_canonical(fs::absolute(original), error);
        if (opened.empty() || !policy_allows(*policy, scene_file, opened)) {
            ::close(fd);
            throw InputError(
                InputLocation(scene_file, 0, field),
                "a path outside the scene's folder and the database (glpreview --allow-paths-outside to allow it)");
        }
    }
    if (!have_proc) return ConfinedFile(fd, original, {}, original);
    // A private folder (mode 0700, unpredictable name) holding one link to the descriptor under the original name.
    std::string pattern = (fs::temp_directory_path() / "glpreview-file-XXXXXX").string();
    if (::mkdtemp(pattern.data()) == nullptr) {
        const int e = errno;
        ::close(fd);
        throw InputError(InputLocation(fs::temp_directory_path()),
                         std::string("cannot make a private folder: ") + std::strerror(e));
    }
    const fs::path folder(pattern);
    const fs::path link = folder / original.filename();
    if (::symlink(descriptor.c_str(), link.c_str()) != 0) {
        const int e = errno;
        ::close(fd);
        ::rmdir(folder.c_str());
        throw InputError(InputLocation(folder),
                         std::string("cannot make a link in a private folder: ") + std::strerror(e));
    }
    return ConfinedFile(fd, original, folder, link);
}

ConfinedFile::ConfinedFile(ConfinedFile&& other) noexcept
    : fd_(other.fd_),
      original_(std::move(other.original_)),
      folder_(std::move(other.folder_)),
      link_(std::move(other.link_)) {
    other.fd_ = -1;
    other.folder_.clear();
    other.link_.clear();
}

ConfinedFile::~ConfinedFile() {
    if (!folder_.empty()) ::unlink(link_.c_str());
    if (!folder_.empty()) ::rmdir(folder_.c_str());
    if (fd_ >= 0) ::close(fd_);
}

std::string ConfinedFile::in_original_terms(std::string message) const {
    const std::string from = link_.string(), to = original_.string();
    if (from.empty() || from == to) return message;
    for (std::size_t at = message.find(from); at != std::string::npos; at = message.find(from, at + to.size()))
        message.replace(at, from.size(), to);
    return message;
}

}  // namespace metalfit::glpreview
