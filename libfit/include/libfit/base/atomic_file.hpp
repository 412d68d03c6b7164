// Writing output files without ever leaving a half-written one behind.
#pragma once

#include <cstdio>
#include <filesystem>
#include <optional>
#include <span>
#include <string>
#include <string_view>

#include "libfit/base/deferred_signals.hpp"

namespace metalfit {

// Writes `contents` to a temporary file beside `target`, then renames it over `target`.
// Throws InputError naming `target` if the directory cannot be written; nothing is left behind.
void write_file_atomically(const std::filesystem::path& target, std::string_view contents);

struct OutputFile {
    std::filesystem::path path;
    std::string contents;
};

// Writes several files as one unit: each to a temporary file beside its target first, and only when every one was
// written are they renamed into place. On failure the temporaries (and targets that did not exist before) are
// removed. Throws InputError naming the file that failed. Targets must be regular files or not exist.
void write_files_atomically(std::span<const OutputFile> files);

// One output written in pieces that still appears as one unit, for an output too large to hold in memory (the fit
// record of thousands of materials). A regular file (or a new one) gets a temporary beside it, as
// write_file_atomically does, renamed over the target by commit(). Standard output, and a device, FIFO or terminal
// (-o /dev/stdout), get an anonymous temporary that commit() copies out. Without commit() (an error, an exception)
// the temporary is removed and nothing reaches the target. For a file target, SIGINT, SIGTERM and SIGHUP are
// deferred while it lives and write() throws Interrupted once one arrived, so that the temporary goes first.
class StreamedOutputFile {
public:
    struct StandardOutput {};
    // Throws InputError naming `target`, as write_file_atomically does, before anything is written.
    explicit StreamedOutputFile(const std::filesystem::path& target);
    explicit StreamedOutputFile(StandardOutput);
    ~StreamedOutputFile();
    StreamedOutputFile(const StreamedOutputFile&) = delete;
    StreamedOutputFile& operator=(const StreamedOutputFile&) = delete;

    void write(std::string_view text);
    // Puts the whole output in place (rename, or the copy out of the anonymous temporary); nothing can be written after.
    void commit();

private:
    std::filesystem::path target_;  // empty: standard output
    std::optional<DeferredSignals> deferred_;
    std::filesystem::path temporary_;  // the named temporary beside a file target
    int fd_ = -1;                      // its descriptor
    std::FILE* spool_ = nullptr;       // the anonymous temporary of standard output and devices
    bool committed_ = false;
};

}  // namespace metalfit
