#include "libfit/io/layer_materials.hpp"

#include <nlohmann/json.hpp>

#include <cmath>
#include <cstdlib>
#include <sstream>

#include "libfit/base/errors.hpp"
#include "libfit/base/input_file.hpp"
#include "libfit/base/number_text.hpp"
#include "libfit/base/text.hpp"
#include "libfit/io/csv.hpp"

namespace metalfit {
namespace {

// "80nm" → 80, "0.12 um" / "0.12µm" → 120; nullopt when the text does not end in a unit.
std::optional<std::pair<std::string_view, double>> split_unit(std::string_view text) {
    text = trim(text);
    for (const auto& [unit, scale] :
         {std::pair<std::string_view, double>{"nm", 1.0}, {"um", 1000.0}, {"µm", 1000.0}, {"μm", 1000.0}})
        if (text.size() > unit.size() && text.substr(text.size() - unit.size()) == unit)
            return std::pair{text.substr(0, text.size() - unit.size()), scale};
    return std::nullopt;
}

std::string number(double v) {
    std::ostringstream s;
    s.precision(6);
    s << v;
    return s.str();
}

std::string argument_name(std::string_view option, std::string_view text) {
    return std::string(option) + " " + std::string(text);
}

Material constant_index(std::string_view text, double n) {
    Material m;
    m.id = std::string(trim(text));
    m.name = "n = " + number(n);
    m.source = "constant";
    m.index = ComplexIndex{SpectralCurve(ConstantSpectrum{n}), SpectralCurve(ConstantSpectrum{0.0})};
    m.provenance.format = "constant";
    m.provenance.data_type = "constant n, k = 0";
    return m;
}

std::string known_names(const FilmCatalog& films) {
    std::string names;
    for (const CatalogEntry& e : films.catalog.entries()) names += (names.empty() ? "" : ", ") + e.id;
    return names;
}

// The layer's material: a constant, a film-catalog name or a file.
Material layer_material(const FilmCatalog& films, std::string_view option, std::string_view whole,
                        std::string_view text) {
    if (const auto n = whole_number(text)) {
        if (!std::isfinite(*n) || *n <= 0.0 || *n > 1e6)
            throw InputError({argument_name(option, whole)},
                             "index " + number(*n) + " is not a finite number in (0, 1e6]");
        return constant_index(text, *n);
    }
    const std::string name(trim(text));
    if (name.empty()) throw UsageError(argument_name(option, whole) + ": give an index, a material or a file");
    if (!looks_like_path(name)) {
        if (films.catalog.find(name) == nullptr) {
            for (const auto& [id, why] : films.without_visible_data)
                if (id == name) throw UsageError(argument_name(option, whole) + ": " + why);
            throw UsageError(argument_name(option, whole) + ": unknown film or coat material '" + name +
                             "' (known: " + known_names(films) + "; or an index such as 1.5, or a .yml/.csv file)");
        }
        return load_material(films.catalog, name);
    }
    return load_nk_file(std::filesystem::path(name));
}

}  // namespace

FilmCatalog FilmCatalog::load(const std::filesystem::path& data_dir) {
    FilmCatalog films{Catalog::load(data_dir, "films.json"), {}};
    const auto file = data_dir / "films.json";
    const nlohmann::json j = nlohmann::json::parse(read_input_file(file));  // parsed once already: valid
    if (const auto list = j.find("without_visible_data"); list != j.end()) {
        if (!list->is_array()) throw InputError({file, 0, "without_visible_data"}, "expected a list");
        for (std::size_t i = 0; i < list->size(); ++i) {
            const auto& e = (*list)[i];
            if (!e.is_object() || !e.contains("id") || !e["id"].is_string() || !e.contains("why") ||
                !e["why"].is_string())
                throw InputError({file, 0, "without_visible_data[" + std::to_string(i) + "]"},
                                 "expected {\"id\", \"why\"}");
            films.without_visible_data.emplace_back(e["id"].get<std::string>(), e["why"].get<std::string>());
        }
    }
    return films;
}

LayerArgument parse_layer_argument(std::string_view option, std::string_view text) {
    const std::size_t colon = text.rfind(':');
    if (colon == std::string_view::npos) return {std::string(text), std::nullopt};
    const std::string_view thickness = text.substr(colon + 1);
    if (const auto split = split_unit(thickness)) {
        const auto value = whole_number(split->first);
        if (!value)
            throw UsageError(argument_name(option, text) + ": thickness '" + std::string(thickness) +
                             "' is not a number with a unit (80nm, 0.08um)");
        return {std::string(text.substr(0, colon)), *value * split->second};
    }
    if (whole_number(thickness))
        throw UsageError(argument_name(option, text) + ": give the thickness's unit (" + std::string(trim(thickness)) +
                         "nm or um)");
    return {std::string(text), std::nullopt};  // a ':' that is part of a file name
}

ThinFilm load_film(const FilmCatalog& films, std::string_view text) {
    const LayerArgument a = parse_layer_argument("--film", text);
    if (!a.thickness_nm)
        throw UsageError("--film " + std::string(text) + ": give the film's thickness with a unit (" + a.material +
                         ":80nm)");
    if (const std::string problem = film_thickness_problem(*a.thickness_nm); !problem.empty())
        throw InputError({argument_name("--film", text)}, problem);
    return {layer_material(films, "--film", text, a.material), *a.thickness_nm};
}

LayerMaterial load_film_material(const FilmCatalog& films, std::string_view text) {
    const LayerArgument a = parse_layer_argument("--film", text);
    if (a.thickness_nm)
        throw UsageError("--film " + std::string(text) + ": the thicknesses come from --thickness; give --film " +
                         a.material + " alone");
    return layer_material(films, "--film", text, a.material);
}

ClearCoat load_coat(const FilmCatalog& films, std::string_view text) {
    const LayerArgument a = parse_layer_argument("--coat", text);
    if (a.thickness_nm)
        if (const std::string problem = coat_thickness_problem(*a.thickness_nm); !problem.empty())
            throw InputError({argument_name("--coat", text)}, problem);
    Material m = layer_material(films, "--coat", text, a.material);
    if (m.source == "constant") {
        const double n = m.index.n(550.0, Interpolation::linear, OutOfRange::clamp);
        if (n < 1.0)
            throw InputError({argument_name("--coat", text)},
                             "index " + number(n) + " is below 1: a coat is a dielectric at least as dense as air");
    }
    return {std::move(m), a.thickness_nm};
}

LayerStack load_layers(const FilmCatalog& films, std::string_view film, std::string_view coat) {
    LayerStack stack;
    if (!film.empty()) stack.film = load_film(films, film);
    if (!coat.empty()) stack.coat = load_coat(films, coat);
    return stack;
}

std::vector<std::string> layer_warnings(const LayerStack& layers) {
    std::vector<std::string> warnings;
    if (layers.film)
        for (const std::string& w : layers.film->material.warnings)
            warnings.push_back("film " + layers.film->material.id + ": " + w);
    if (layers.coat)
        for (const std::string& w : layers.coat->material.warnings)
            warnings.push_back("coat " + layers.coat->material.id + ": " + w);
    return warnings;
}

}  // namespace metalfit
