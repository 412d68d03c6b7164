// Importer for user n,k tables in CSV.
#pragma once

#include <filesystem>

#include "libfit/io/material.hpp"

namespace metalfit {

// Reads an n,k table: a header line naming the columns, then one row per wavelength (docs/data.md, "Your own
// files"). Fields separated by commas, semicolons (then "0,43" is a decimal comma), tabs or spaces, as the header
// line does; a UTF-8 byte-order mark and CRLF line ends are accepted. Columns: wavelength (nm, µm, Å), energy (eV)
// or wavenumber (cm⁻¹); n and k, or ε₁ and ε₂; other named columns are ignored with a warning. A later header line
// starts a new block (refractiveindex.info's CSV download: `wl,n` rows, then `wl,k` rows, wl in µm). Blank lines and
// lines starting with '#' are ignored. Throws InputError naming the file and line.
Material load_nk_csv(const std::filesystem::path& file);

// Dispatches on the extension: .yml/.yaml → refractiveindex.info, .csv/.tsv/.txt/.dat → load_nk_csv.
Material load_nk_file(const std::filesystem::path& file);

}  // namespace metalfit
