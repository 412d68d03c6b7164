// Content digests of input files, for provenance.
#pragma once

#include <filesystem>
#include <string>

namespace metalfit {

// Lower-case hex SHA-256 of the file's bytes (OpenSSL). Throws InputError if it cannot be read.
std::string sha256_file(const std::filesystem::path& file);

}  // namespace metalfit
