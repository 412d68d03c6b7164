// Importer for refractiveindex.info database YAML files.
#pragma once

#include <filesystem>

#include "libfit/io/material.hpp"

namespace metalfit {

// Reads a refractiveindex.info YAML file: DATA blocks `tabulated nk`, `tabulated n`, `tabulated k`
// (n and k may come in separate blocks on different grids), `formula 1`, `formula 2`. Wavelengths
// are converted from µm to nm. REFERENCES, COMMENTS and CONDITIONS (anywhere in the file) are kept.
// A file with n only loads with k = 0 and a warning. Throws InputError naming file and line/field.
Material load_refractiveindex_yaml(const std::filesystem::path& file);

}  // namespace metalfit
