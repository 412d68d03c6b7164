// Content digests of input files, for provenance.
#pragma once

#include <filesystem>
#include <string>
#include <string_view>

namespace metalfit {

// Lower-case hex SHA-256 of the file's bytes (OpenSSL). Throws InputError if it cannot be read.
std::string sha256_file(const std::filesystem::path& file);
// The same of bytes already read (read_input_file): the digest of exactly what was parsed.
std::string sha256_bytes(std::string_view bytes);

}  // namespace metalfit
