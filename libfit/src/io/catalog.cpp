#include "libfit/io/catalog.hpp"

#include <nlohmann/json.hpp>

#include <algorithm>
#include <fstream>

#include "libfit/base/errors.hpp"
#include "libfit/base/input_file.hpp"
#include "libfit/base/text.hpp"
#include "libfit/base/utf8.hpp"
#include "libfit/io/csv.hpp"

#include "io/json_fields.hpp"

namespace metalfit {
namespace {

CatalogSource read_source(const nlohmann::json& j, const std::filesystem::path& file,
                          const std::filesystem::path& data_dir, const std::string& where) {
    if (!j.is_object()) throw InputError({file, 0, where}, "expected an object");
    CatalogSource s;
    s.source = io_detail::string_field(j, "source", file, where);
    s.file = data_dir / io_detail::string_field(j, "file", file, where);
    s.reference = io_detail::string_field(j, "reference", file, where);
    s.doi = io_detail::string_field(j, "doi", file, where, false);
    s.licence = io_detail::string_field(j, "licence", file, where);
    s.database_path = io_detail::string_field(j, "database_path", file, where, false);
    s.note = io_detail::string_field(j, "note", file, where, false);
    const auto range = j.find("range_nm"), points = j.find("points_360_830");
    if ((range == j.end()) != (points == j.end()))
        throw InputError({file, 0, where + (range == j.end() ? ".range_nm" : ".points_360_830")},
                         "missing (range_nm and points_360_830 come together)");
    if (range != j.end()) {
        if (!range->is_array() || range->size() != 2 || !(*range)[0].is_number() || !(*range)[1].is_number() ||
            !((*range)[0].get<double>() < (*range)[1].get<double>()))
            throw InputError({file, 0, where + ".range_nm"}, "expected [min, max] in nm");
        if (!points->is_number_unsigned())
            throw InputError({file, 0, where + ".points_360_830"}, "expected a non-negative integer");
        s.coverage =
            CatalogCoverage{{(*range)[0].get<double>(), (*range)[1].get<double>()}, points->get<std::size_t>()};
    }
    return s;
}

}  // namespace

const CatalogSource& CatalogEntry::find_source(std::string_view source) const {
    if (source.empty() || equal_ignoring_case(source, primary.source)) return primary;
    for (const auto& a : alternates)
        if (equal_ignoring_case(source, a.source)) return a;
    std::string available = primary.source;
    for (const auto& a : alternates) available += ", " + a.source;
    throw UsageError("material " + id + " has no source '" + std::string(source) + "' (available: " + available + ")");
}

Catalog Catalog::load(const std::filesystem::path& data_dir, std::string_view file_name) {
    const auto file = data_dir / file_name;
    // Every data file's path starts with the folder's, and records carry them (UTF-8): $METALFIT_DATA may be anything.
    if (const auto problem = find_invalid_utf8(file.native()))
        throw InputError({file}, "the path of the database is not UTF-8 (" + problem->reason + "); rename the folder");
    std::error_code missing;
    if (!std::filesystem::exists(file, missing))
        throw InputError({file}, "cannot open the catalog (set $METALFIT_DATA to the data folder)");
    const std::string text = read_input_file(file);
    nlohmann::json j;
    try {
        j = nlohmann::json::parse(text);
    } catch (const nlohmann::json::exception& e) {  // parse_error, and out_of_range for a number like 1e999
        throw InputError({file}, std::string("invalid JSON: ") + e.what());
    }
    const auto materials = j.find("materials");
    if (materials == j.end() || !materials->is_array()) throw InputError({file, 0, "materials"}, "expected a list");
    Catalog catalog;
    catalog.data_dir_ = data_dir;
    for (std::size_t i = 0; i < materials->size(); ++i) {
        const auto& m = (*materials)[i];
        const std::string where = "materials[" + std::to_string(i) + "]";
        if (!m.is_object()) throw InputError({file, 0, where}, "expected an object");
        CatalogEntry e;
        e.id = io_detail::string_field(m, "id", file, where);
        e.name = io_detail::string_field(m, "name", file, where);
        e.kind = io_detail::string_field(m, "kind", file, where, false);
        if (auto a = m.find("aliases"); a != m.end()) {
            if (!a->is_array()) throw InputError({file, 0, where + ".aliases"}, "expected a list of strings");
            for (const auto& alias : *a) {
                if (!alias.is_string()) throw InputError({file, 0, where + ".aliases"}, "expected a list of strings");
                e.aliases.push_back(alias.get<std::string>());
            }
        }
        if (!m.contains("primary")) throw InputError({file, 0, where + ".primary"}, "missing");
        e.primary = read_source(m["primary"], file, data_dir, where + ".primary");
        if (auto a = m.find("alternates"); a != m.end()) {
            if (!a->is_array()) throw InputError({file, 0, where + ".alternates"}, "expected a list");
            for (std::size_t k = 0; k < a->size(); ++k)
                e.alternates.push_back(
                    read_source((*a)[k], file, data_dir, where + ".alternates[" + std::to_string(k) + "]"));
        }
        catalog.entries_.push_back(std::move(e));
    }
    return catalog;
}

const CatalogEntry* Catalog::find(std::string_view name) const {
    for (const auto& e : entries_) {
        if (equal_ignoring_case(name, e.id) || equal_ignoring_case(name, e.name)) return &e;
        for (const auto& alias : e.aliases)
            if (equal_ignoring_case(name, alias)) return &e;
    }
    return nullptr;
}

bool looks_like_path(std::string_view argument) {
    if (argument.find('/') != std::string_view::npos) return true;
    const std::filesystem::path p(argument);
    std::string ext = p.extension().string();
    std::transform(ext.begin(), ext.end(), ext.begin(), [](unsigned char c) { return std::tolower(c); });
    return ext == ".yml" || ext == ".yaml" || ext == ".csv" || ext == ".tsv" || ext == ".txt" || ext == ".dat";
}

Material load_material(const Catalog& catalog, std::string_view material_or_path, std::string_view source,
                       const UserFileLabels& labels) {
    if (const CatalogEntry* entry = catalog.find(material_or_path);
        entry != nullptr && !looks_like_path(material_or_path)) {
        if (!labels.empty())
            throw UsageError("--name and --reference label a file of your own, not the catalog material '" + entry->id +
                             "' (its reference is in the catalog)");
        const CatalogSource& s = entry->find_source(source);
        Material m = load_nk_file(s.file);
        m.id = entry->id;
        m.name = entry->name;
        m.source = s.source;
        m.provenance.references = s.reference + (s.doi.empty() ? "" : ", doi:" + s.doi);
        m.provenance.note = s.note;
        return m;
    }
    if (looks_like_path(material_or_path)) {
        if (!source.empty()) throw UsageError("an alternate source applies to catalog materials, not to a file");
        Material m = load_nk_file(std::filesystem::path(material_or_path));
        if (!labels.name.empty()) m.id = m.name = labels.name;
        if (!labels.reference.empty()) m.provenance.references = labels.reference;
        return m;
    }
    std::error_code ec;
    if (std::filesystem::is_regular_file(std::filesystem::path(material_or_path), ec))
        throw UsageError("unknown material '" + std::string(material_or_path) +
                         "' (see `metalfit list`); a file of that name is here, but files are read by their extension "
                         "(.yml, .yaml, .csv, .tsv, .txt or .dat): rename it, or give it as a path with one");
    throw UsageError("unknown material '" + std::string(material_or_path) +
                     "' (see `metalfit list`, or give a .yml/.csv path)");
}

}  // namespace metalfit
