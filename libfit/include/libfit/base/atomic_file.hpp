// Writing output files without ever leaving a half-written one behind.
#pragma once

#include <filesystem>
#include <span>
#include <string>
#include <string_view>

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

}  // namespace metalfit
