// Importer for user n,k tables in CSV.
#pragma once

#include <filesystem>

#include "libfit/io/material.hpp"

namespace metalfit {

// Reads a CSV file with the header `wavelength_nm,n,k` or `wavelength_um,n,k`, one row per
// wavelength. Blank lines and lines starting with '#' are ignored. Throws InputError naming the
// file and line.
Material load_nk_csv(const std::filesystem::path& file);

// Dispatches on the extension: .yml/.yaml → refractiveindex.info, .csv → CSV.
Material load_nk_file(const std::filesystem::path& file);

}  // namespace metalfit
