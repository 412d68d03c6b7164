// A file a scene names (a material table, the equirect image), opened once and checked on the open descriptor: what
// the readers then read is exactly the file that was checked, whatever happens to the path after the check (a link
// swapped in between the check and the read cannot lead a read outside the scene's folder and the database).
#pragma once

#include <filesystem>
#include <optional>
#include <string>

#include "glpreview/scene/scene.hpp"

namespace metalfit::glpreview {

class ConfinedFile {
public:
    // Opens `file` (without blocking on a FIFO), checks on the descriptor that it is a regular file and, under a
    // policy, that the file actually opened (its /proc/self/fd name, links resolved by the kernel) lies in the scene's
    // folder or the database. Throws InputError naming the scene file and `field`.
    // Without a policy (library use) only the regular-file check applies. A relative `file` is beside the scene file.
    static ConfinedFile open(const std::filesystem::path& scene_file, const std::optional<PathPolicy>& policy,
                             const std::filesystem::path& file, const std::string& field);
    static ConfinedFile open(const Scene& scene, const std::filesystem::path& file, const std::string& field) {
        return open(scene.file, scene.paths, file, field);
    }

    ConfinedFile(ConfinedFile&& other) noexcept;
    ConfinedFile& operator=(ConfinedFile&&) = delete;
    ConfinedFile(const ConfinedFile&) = delete;
    ~ConfinedFile();

    // A path that reads the descriptor's file and keeps the original file name (readers choose a format by its
    // extension): a link to /proc/self/fd/N in a private folder of this process.
    const std::filesystem::path& path() const { return link_; }
    // The path as the scene gave it (resolved against the scene's folder): what messages and records name.
    const std::filesystem::path& original() const { return original_; }
    // `message` with the private path replaced by the original one.
    std::string in_original_terms(std::string message) const;

private:
    ConfinedFile(int fd, std::filesystem::path original, std::filesystem::path folder, std::filesystem::path link)
        : fd_(fd), original_(std::move(original)), folder_(std::move(folder)), link_(std::move(link)) {}
    int fd_ = -1;
    std::filesystem::path original_, folder_, link_;
};

}  // namespace metalfit::glpreview
