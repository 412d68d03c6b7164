// The built-in spectral metal database: data/catalog.json and the files it names.
#pragma once

#include <filesystem>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

#include "libfit/io/material.hpp"

namespace metalfit {

// What a table covers, as written in the catalog by scripts/catalog-coverage.py (so that listing the catalog parses
// no table); CatalogCoverage.MetadataMatchesEveryTable checks it against the tables.
struct CatalogCoverage {
    WavelengthRange range_nm;        // where n and k are both defined
    std::size_t points_360_830 = 0;  // tabulated samples of n inside 360–830 nm
};

struct CatalogSource {
    std::string source;          // "Johnson"
    std::filesystem::path file;  // absolute path of the nk file
    std::string reference;
    std::string doi;  // empty when none
    std::string licence;
    std::string database_path;  // path in the refractiveindex.info repository
    std::string note;
    std::optional<CatalogCoverage> coverage;  // absent in catalogs written without it
};

struct CatalogEntry {
    std::string id;    // "Au"
    std::string name;  // "gold"
    std::string kind;  // "metal", "alloy", "intermetallic", "nitride"
    std::vector<std::string> aliases;
    CatalogSource primary;
    std::vector<CatalogSource> alternates;

    // The primary when `source` is empty, else the source of that name (case-insensitive).
    // Throws UsageError listing the available sources.
    const CatalogSource& find_source(std::string_view source) const;
};

class Catalog {
public:
    // Reads <data_dir>/catalog.json (or another catalog of the same form beside it, e.g. films.json). Throws
    // InputError naming the file and field.
    static Catalog load(const std::filesystem::path& data_dir, std::string_view file_name = "catalog.json");

    // Case-insensitive match on id, name or alias; nullptr when unknown.
    const CatalogEntry* find(std::string_view name) const;
    const std::vector<CatalogEntry>& entries() const { return entries_; }
    const std::filesystem::path& data_dir() const { return data_dir_; }

private:
    std::filesystem::path data_dir_;
    std::vector<CatalogEntry> entries_;
};

// True when `argument` names a file rather than a catalog material: it contains a path separator or has a
// .yml/.yaml/.csv/.tsv/.txt/.dat extension. Whether a file of that name exists plays no part, so a file named "Au" in
// the current folder never shadows the catalog's gold: a path must look like a path ("./Au").
bool looks_like_path(std::string_view argument);

// What a user says about a file of their own (`--name`, `--reference`): shown and exported instead of the file stem
// and the file's own REFERENCES. Empty fields change nothing.
struct UserFileLabels {
    std::string name;       // the material's name and id ("my gold")
    std::string reference;  // the literature reference ("A. Author, J. Opt. 1, 2 (2020)")

    bool empty() const { return name.empty() && reference.empty(); }
};

// Loads a catalog material (optionally a named alternate source) or a user file, with provenance; `labels` apply to
// a user file only. Unknown material or source, or labels for a catalog material: UsageError; bad file: InputError.
Material load_material(const Catalog& catalog, std::string_view material_or_path, std::string_view source = {},
                       const UserFileLabels& labels = {});

}  // namespace metalfit
