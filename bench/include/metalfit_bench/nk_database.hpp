// The metal nk files of a refractiveindex.info database folder (its layout, `data/<shelf>/<book>/nk/<page>.yml`, or
// any folder of such files, as data/nk is): what `metalfit bench --scaling-database FOLDER` fits.
#pragma once

#include <cstddef>
#include <filesystem>
#include <vector>

#include "libfit/io/material.hpp"

namespace metalfit::bench {

// Metal enough to fit: the median of k over 360–830 nm (10 nm steps) is at least 1 (metals, alloys, metallic nitrides
// and carbides; not glasses, not semiconductors such as Si, not files without k).
inline constexpr double kMetalMedianK = 1.0;
bool is_metal(const Material& material);

struct NkDatabaseScan {
    std::filesystem::path folder;
    std::vector<std::filesystem::path> metal_files;  // sorted by path
    std::size_t files = 0;                           // regular files found (links to files included)
    std::size_t not_nk = 0;           // not a .yml/.yaml file, or under a folder that holds no n, k data (n2)
    std::size_t unreadable = 0;       // the importer refused it (docs/data.md), or it could not be read
    std::size_t outside_visible = 0;  // n or k does not cover 360–830 nm
    std::size_t not_metal = 0;        // is_metal is false
    double cpu_s = 0;                 // thread CPU of the scan (each file read and classified, then let go)
};

// Walks `folder` (recursively; folders that cannot be opened are passed over) and classifies every regular file,
// loading one at a time. Throws InputError when `folder` is not a folder.
NkDatabaseScan scan_nk_database(const std::filesystem::path& folder);

}  // namespace metalfit::bench
