// How every record, header and JSON metalfit writes names an input file: never an absolute path of the machine, so
// that records made on two machines (or in two checkouts) compare equal and say nothing about the machine's folders.
// The convention (docs/fit-record.md, "Paths in records"):
// - a file inside the database folder (`data_dir`): "data:" and its path relative to that folder, '/'-separated
//   ("data:nk/Au/Johnson.yml", "data:ocio/config.ocio"); the database wins when the working folder holds it too;
// - else a file below the current working folder: its path relative to that folder ("gold.csv", "inputs/gold.csv"),
//   written "./data:x" should it begin with one of the two markers;
// - else (outside both): "outside:" and the file name alone ("outside:gold.csv").
#pragma once

#include <filesystem>
#include <string>
#include <string_view>
#include <vector>

namespace metalfit {

inline constexpr std::string_view kDataPathMarker = "data:";
inline constexpr std::string_view kOutsidePathMarker = "outside:";

// `file` (absolute or relative to the working folder) as records write it; "" for no file (an empty path). Never
// throws; never starts with '/'.
std::string record_path(const std::filesystem::path& file, const std::filesystem::path& data_dir);

// Messages about `file` (importer warnings name it as the user gave it: "/home/me/gold.yml:22: …") as records write
// them: each absolute spelling of `file` (as given, and its absolute normal form) replaced by record_path(file,
// data_dir). A file given by a relative path is left as it is: it is its own record path or a path below the
// working folder.
std::vector<std::string> record_messages(const std::vector<std::string>& messages, const std::filesystem::path& file,
                                         const std::filesystem::path& data_dir);

}  // namespace metalfit
