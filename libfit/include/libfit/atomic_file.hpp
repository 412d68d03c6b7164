// Writing output files without ever leaving a half-written one behind.
#pragma once

#include <filesystem>
#include <string_view>

namespace metalfit {

// Writes `contents` to a temporary file beside `target`, then renames it over `target`.
// Throws InputError naming `target` if the directory cannot be written; nothing is left behind.
void write_file_atomically(const std::filesystem::path& target, std::string_view contents);

}  // namespace metalfit
