#include "list_record.hpp"

#include "libfit/io/material.hpp"

namespace metalfit::cli {
namespace {

// The coverage from the catalog's metadata; only a catalog written without it makes the table be parsed.
CatalogCoverage coverage_of(const Catalog& catalog, const CatalogEntry& entry) {
    if (entry.primary.coverage) return *entry.primary.coverage;
    const Material m = load_material(catalog, entry.id);
    return {m.index.range(), m.index.n.tabulated_points_in(kVisibleRange)};
}

nlohmann::json describe(const CatalogEntry& entry, const CatalogCoverage& coverage) {
    const WavelengthRange r = coverage.range_nm;
    nlohmann::json alternates = nlohmann::json::array();
    for (const auto& a : entry.alternates) alternates.push_back(a.source);
    return {{"id", entry.id},
            {"name", entry.name},
            {"kind", entry.kind},
            {"source", entry.primary.source},
            {"alternates", alternates},
            {"range_nm", {r.min_nm, r.max_nm}},
            {"points_360_830", coverage.points_360_830},
            {"covers_360_830", r.covers(kVisibleRange)},
            {"reference", entry.primary.reference},
            {"note", entry.primary.note}};
}

}  // namespace

nlohmann::json list_record(const Catalog& catalog) {
    nlohmann::json rows = nlohmann::json::array();
    for (const auto& entry : catalog.entries()) rows.push_back(describe(entry, coverage_of(catalog, entry)));
    return rows;
}

}  // namespace metalfit::cli
