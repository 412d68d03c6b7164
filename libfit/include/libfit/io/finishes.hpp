// Named finishes (data/finishes.json): a catalog metal with a thin film and/or a clear coat under one name
// ("anodized-ti-80nm", "tempered-steel-blue", "lacquered-brass"), usable wherever a material name is. The layers are
// written as --film and --coat arguments and loaded by io/layer_materials, so a finish is exactly the command line
// it stands for. docs/colour.md, "Named finishes".
#pragma once

#include <filesystem>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

#include "libfit/io/catalog.hpp"
#include "libfit/io/layer_materials.hpp"

namespace metalfit {

struct Finish {
    std::string id;    // "anodized-ti-80nm"
    std::string name;  // "anodized titanium, 80 nm"
    std::vector<std::string> aliases;
    std::string metal;  // a catalog material ("Ti")
    std::string film;   // a --film argument ("TiO2:80nm"); empty: none
    std::string coat;   // a --coat argument ("1.49"); empty: none
    std::string note;
    std::vector<std::string> sources;
};

class FinishCatalog {
public:
    // Reads <data_dir>/finishes.json; a database without one has no finishes. Throws InputError naming the file and
    // field.
    static FinishCatalog load(const std::filesystem::path& data_dir);

    // Case-insensitive match on id, name or alias; nullptr when unknown.
    const Finish* find(std::string_view name) const;
    const std::vector<Finish>& entries() const { return entries_; }
    const std::filesystem::path& file() const { return file_; }

private:
    std::filesystem::path file_;
    std::vector<Finish> entries_;
};

// The finish's metal (its primary source, or `source`) with its layers: the id is the finish's, the name, source and
// provenance the metal's, and the stack record names the finish. A film or coat the database cannot load is an
// InputError naming finishes.json and the field.
Material load_finish(const Finish& finish, const FinishCatalog& finishes, const Catalog& metals,
                     const FilmCatalog& films, std::string_view source = {});

// `name` as a finish where it is one: not a file, not a catalog material, and a finish of <data_dir>/finishes.json
// (load_finish with that source); nullopt otherwise (the caller loads it as a material, with that call's errors).
std::optional<Material> load_finish_named(const Catalog& metals, std::string_view name, std::string_view source = {});

}  // namespace metalfit
