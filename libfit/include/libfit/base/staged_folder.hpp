// A folder of output files replaced as one unit: staged beside it, switched in with one rename (docs/export.md,
// "One unit").
#pragma once

#include <filesystem>
#include <functional>
#include <span>
#include <string>

#include "libfit/base/atomic_file.hpp"

namespace metalfit {

// For a new file whose path already holds a file in the folder: the contents to write instead of `mine` (an index
// merged with the entries already there), given the file's path relative to the folder and its current contents.
// May throw (InputError or UsageError) to refuse the whole update.
using MergeExisting =
    std::function<std::string(const std::filesystem::path& relative, const std::string& existing, const std::string& mine)>;

// Writes `files` (paths relative to `dir`) into `dir` as one unit, keeping every other file already there:
// 1. the folders above `dir` are created if missing (a folder another process creates meanwhile is not an error);
// 2. a lock on the folder above `dir` serialises writers of that folder; staging folders that killed writers left
//    (".<name>.metalfit-staging.*" beside `dir`) are removed;
// 3. a new folder ".<name>.metalfit-staging.XXXXXX" beside `dir` receives hard links to the files already in `dir`
//    (copies where a link is refused), then the new files (created exclusively, never through a link);
// 4. one rename switches it in: renameat2(RENAME_EXCHANGE) with an existing folder, then the old one is removed.
// SIGINT, SIGTERM and SIGHUP are deferred meanwhile (DeferredSignals): the staging folder is removed first. A
// SIGKILL leaves the old folder or the new one, plus at most a staging folder that the next writer removes.
// Throws InputError naming the file or folder that failed (nothing is changed then), UsageError when `dir` is the
// current folder or one above it (the switch would leave the shell in the old, removed folder).
void update_folder_as_unit(const std::filesystem::path& dir, std::span<const OutputFile> files,
                           const MergeExisting& merge = {});

}  // namespace metalfit
