// Where a film's or a coat's material comes from: a constant index ("2.2"), a name of the database's film and coat
// tables (data/films.json: "TiO2", "PMMA", …) or a file of any format an n,k table can have, and its thickness
// ("TiO2:80nm", "my-oxide.csv:0.12um"). What `--film` and `--coat` accept (docs/cli.md, "Layers").
#pragma once

#include <filesystem>
#include <optional>
#include <string>
#include <string_view>
#include <utility>
#include <vector>

#include "libfit/io/catalog.hpp"
#include "libfit/io/layer_stack.hpp"

namespace metalfit {

// The film and coat tables: <data_dir>/films.json (the catalog's form), and the materials it knows to have no
// visible data (id and why), which are refused with that reason instead of "unknown".
struct FilmCatalog {
    Catalog catalog;
    std::vector<std::pair<std::string, std::string>> without_visible_data;

    // Reads <data_dir>/films.json. Throws InputError naming the file and field.
    static FilmCatalog load(const std::filesystem::path& data_dir);
};

// "MATERIAL[:THICKNESS]" split at its last ':' when what follows is a thickness (a number and nm, um or µm).
// `option` ("--film") names the argument in messages. A thickness without a unit or not a number: UsageError.
// Thickness and index values themselves are checked by load_film and load_coat.
struct LayerArgument {
    std::string material;
    std::optional<double> thickness_nm;
};
LayerArgument parse_layer_argument(std::string_view option, std::string_view text);

// `--film IOR|MATERIAL|FILE:THICKNESS`: a missing thickness or an unknown name: UsageError (exit 2); a thickness
// that is negative, not finite or beyond 2 µm, an index that is not a finite positive number, a bad file:
// InputError naming the option or the file (exit 3).
ThinFilm load_film(const FilmCatalog& films, std::string_view text);
// `--film IOR|MATERIAL|FILE` without a thickness (the oxide chart's film, its thicknesses given apart): the material
// alone, with load_film's errors; a thickness given: UsageError.
LayerMaterial load_film_material(const FilmCatalog& films, std::string_view text);
// `--coat IOR|MATERIAL|FILE[:THICKNESS]`: as load_film; a constant index below 1 is InputError (a table's index is
// checked on the colour grid by the reference curve).
ClearCoat load_coat(const FilmCatalog& films, std::string_view text);

// `--film` and `--coat` together, either empty for none: the stack as load_film and load_coat load it (their errors).
// The CLI's layer options and glpreview's sphere keys `film` and `coat`.
LayerStack load_layers(const FilmCatalog& films, std::string_view film, std::string_view coat);
// The layers' own warnings (a table held constant at its ends, ...), each prefixed with its layer ("film TiO2: ...").
std::vector<std::string> layer_warnings(const LayerStack& layers);

}  // namespace metalfit
