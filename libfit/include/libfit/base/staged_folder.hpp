// A folder of output files replaced as one unit: staged beside it, switched in with one exchange (docs/export.md,
// "One unit"; docs/cli.md, "Output files and interrupted runs").
#pragma once

#include <filesystem>
#include <functional>
#include <optional>
#include <span>
#include <string>
#include <string_view>
#include <vector>

#include "libfit/base/atomic_file.hpp"
#include "libfit/base/deferred_signals.hpp"

namespace metalfit {

// For a new file whose path already holds a file in the folder: the contents to write instead of `mine` (an index
// merged with the entries already there), given the file's path relative to the folder and its current contents.
// May throw (InputError or UsageError) to refuse the whole update.
using MergeExisting = std::function<std::string(const std::filesystem::path& relative, const std::string& existing,
                                                const std::string& mine)>;

// The one mechanism every writer of an output folder goes through (export, report, glpreview):
// 1. construction: the folders above `dir` are created if missing; staging folders that killed writers left beside
//    `dir` are removed (only names provably a writer's own: ".<name>.metalfit-staging.<pid>.<random>", owned by this
//    user, whose pid is gone and whose lock is free; never a user's file); a new staging folder of that name is made
//    beside `dir` (exclusively, unpredictable) and locked (an OFD lock) while this object lives; SIGINT, SIGTERM and
//    SIGHUP are deferred (DeferredSignals) until it is destroyed, so that the staging is removed first;
// 2. the caller writes its files into the staging folder (write(), or file() for a library that writes by path);
// 3. commit(), under a lock on the folder above `dir` (one committer at a time): with keep_other_files the files
//    already in `dir` that the caller did not write are carried over (hard links, copies where refused; `merge`
//    decides for files written again), with replace_folder the folder becomes exactly the staged files; then
//    renameat2(RENAME_EXCHANGE) swaps the staging and `dir` — at every instant either the old or the new folder is
//    at the name — and the old folder, now under the staging name, is removed.
// A link inside the old folder is never written through: a new file at its path replaces it, and a folder the
// caller writes into that is a link in the old folder is refused (InputError naming it; nothing is changed).
// A SIGKILL leaves the old folder or the new one, plus at most a staging folder that the next writer removes.
// Errors: InputError naming the file or folder that failed (nothing is changed then), UsageError when `dir` is the
// current folder or one above it (the switch would leave the shell in the old, removed folder).
class StagedFolder {
public:
    enum class Existing { keep_other_files, replace_folder };

    explicit StagedFolder(const std::filesystem::path& dir, Existing existing = Existing::keep_other_files,
                          MergeExisting merge = {});
    ~StagedFolder();  // without commit(): the staging (and the folders above `dir` it created) removed
    StagedFolder(const StagedFolder&) = delete;
    StagedFolder& operator=(const StagedFolder&) = delete;

    // The folder written (absolute, a link at `dir` followed).
    const std::filesystem::path& folder() const { return dir_; }
    // Where to write `relative` now (its folders made in the staging); relative, without "..". Throws Interrupted
    // when a deferred signal arrived.
    std::filesystem::path file(const std::filesystem::path& relative);
    // Writes `relative` in the staging (created exclusively, never through a link). Throws InputError naming dir/relative.
    void write(const std::filesystem::path& relative, std::string_view contents);
    // Switches the staged files in as described above; nothing can be written after.
    void commit();

private:
    DeferredSignals deferred_;  // first: destroyed last, after the staging went
    std::filesystem::path requested_, dir_, staging_;
    Existing existing_;
    MergeExisting merge_;
    std::vector<std::filesystem::path> created_;  // folders above dir_ this object made
    int staging_fd_ = -1;                         // holds the staging's lock
    bool committed_ = false;
};

// Writes `files` (paths relative to `dir`) into `dir` as one unit, keeping every other file already there
// (StagedFolder with keep_other_files).
void update_folder_as_unit(const std::filesystem::path& dir, std::span<const OutputFile> files,
                           const MergeExisting& merge = {});

// Makes `dir` hold exactly `files` as one unit (StagedFolder with replace_folder): the report folder.
void replace_folder_as_unit(const std::filesystem::path& dir, std::span<const OutputFile> files);

}  // namespace metalfit
