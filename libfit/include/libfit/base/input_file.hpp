// Reading an input file with bounded cost (docs/cli.md, "Limits"): regular files only, of a bounded size.
#pragma once

#include <cstddef>
#include <filesystem>
#include <string>

namespace metalfit {

// The largest n,k table, catalog or other text input metalfit reads (the database's largest file is 59 KB).
inline constexpr std::size_t kMaxInputFileBytes = std::size_t{16} << 20;
// The most data rows of one n,k table (the database's longest has about 2,000).
inline constexpr std::size_t kMaxTableRows = 100000;

// The bytes of `file`. InputError naming the file when it cannot be opened, is not a regular file (a FIFO, device or
// directory: such a file is refused before it is read, so /dev/zero or a FIFO cannot hang or fill memory), or holds
// more than `max_bytes`.
std::string read_input_file(const std::filesystem::path& file, std::size_t max_bytes = kMaxInputFileBytes);

}  // namespace metalfit
