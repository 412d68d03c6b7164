#include "libfit/fit/physicallybased_table.hpp"

#include <algorithm>
#include <set>

#include "libfit/base/version.hpp"
#include "libfit/models/gulbrandsen/gulbrandsen.hpp"
#include "libfit/models/schlick/schlick.hpp"

namespace metalfit {

namespace {

using Json = nlohmann::ordered_json;

double gulbrandsen_at_f82(double r, double g) {
    const double p[2] = {r, g};
    return models::Gulbrandsen::evaluate(p, kMuF82);
}

PhysicallyBasedLook look_of(const ReferenceCurve& curve) {
    PhysicallyBasedLook look;
    look.f0 = curve(1.0);
    const RGB f82 = curve(kMuF82);
    const double r_max = models::Gulbrandsen::kParameters[0].upper;
    for (int c = 0; c < 3; ++c) {
        const double f0 = look.f0[c];
        look.f82_tint[c] = f82[c] / models::Schlick::evaluate(&f0, kMuF82);
        const double r = std::clamp(f0, 0.0, r_max);
        look.edge_tint[c] = gulbrandsen_edge_tint_at_f82(r, f82[c]);
        look.eta[static_cast<std::size_t>(c)] = models::Gulbrandsen::to_nk(r, look.edge_tint[c]);
    }
    return look;
}

Json triple(const RGB& v) { return Json::array({v.r, v.g, v.b}); }

Json in_spaces(const RGB& srgb_linear, const RGB& acescg) {
    return Json::array({{{"colorSpace", "srgb-linear"}, {"color", triple(srgb_linear)}},
                        {{"colorSpace", "acescg"}, {"color", triple(acescg)}}});
}

Json complex_ior(const char* space, const PhysicallyBasedLook& look) {
    Json n = Json::array(), k = Json::array();
    for (const auto& eta : look.eta) {
        n.push_back(eta.real());
        k.push_back(eta.imag());
    }
    return {{"colorSpace", space}, {"n", n}, {"k", k}};
}

Json references(const PhysicallyBasedRow& row) {
    Json refs = Json::array();
    Json paper{{"title", row.reference}};
    if (!row.doi.empty()) {
        paper["url"] = "https://doi.org/" + row.doi;
        paper["doi"] = "https://doi.org/" + row.doi;
    } else {
        paper["url"] = "https://github.com/polyanskiy/refractiveindex.info-database/blob/master/" + row.database_path;
    }
    refs.push_back(paper);
    refs.push_back(
        {{"title", "Refractiveindex.info database of optical constants"},
         {"author", "Polyanskiy, M. N."},
         {"url", "https://github.com/polyanskiy/refractiveindex.info-database/blob/master/" + row.database_path},
         {"doi", "https://doi.org/10.1038/s41597-023-02898-2"},
         {"year", "2024"}});
    return refs;
}

}  // namespace

double gulbrandsen_edge_tint_at_f82(double r, double f82) {
    // Gulbrandsen's R(1/7) rises with g at fixed r: bisection on [0, 1], to the double's resolution.
    double lo = 0.0, hi = 1.0;
    if (f82 <= gulbrandsen_at_f82(r, lo)) return lo;
    if (f82 >= gulbrandsen_at_f82(r, hi)) return hi;
    for (int i = 0; i < 200 && hi - lo > 0.0; ++i) {
        const double mid = 0.5 * (lo + hi);
        if (mid == lo || mid == hi) break;
        (gulbrandsen_at_f82(r, mid) < f82 ? lo : hi) = mid;
    }
    return 0.5 * (lo + hi);
}

PhysicallyBasedTable physicallybased_table(const Catalog& catalog, const PhysicallyBasedColour& colour) {
    PhysicallyBasedTable table{colour.srgb_linear.space(), colour.acescg.space(), {}};
    for (const CatalogEntry& entry : catalog.entries()) {
        const Material material = load_material(catalog, entry.id);
        const ReferenceCurve srgb_linear(material, colour.colorimetry, colour.srgb_linear, colour.spectral);
        const ReferenceCurve acescg(material, colour.colorimetry, colour.acescg, colour.spectral);
        table.rows.push_back({entry.id, entry.name, entry.primary.reference, entry.primary.doi, entry.primary.licence,
                              entry.primary.database_path, look_of(srgb_linear), look_of(acescg)});
    }
    return table;
}

Json physicallybased_json(const PhysicallyBasedTable& table) {
    std::set<std::string> licences;
    for (const PhysicallyBasedRow& r : table.rows) licences.insert(r.licence);
    std::string licence = "CC0 1.0 Universal";
    if (licences != std::set<std::string>{"CC0-1.0"}) {
        licence = "of the sources:";
        for (const std::string& l : licences) licence += " " + (l.empty() ? std::string("unknown") : l);
    }
    Json data = Json::array();
    for (const PhysicallyBasedRow& r : table.rows) {
        const PhysicallyBasedLook &s = r.srgb_linear, &a = r.acescg;
        data.push_back({{"name", r.name},
                        {"color", in_spaces(s.f0, a.f0)},
                        {"metalness", 1},
                        {"specularColor",
                         Json::array({{{"format", Json::array({"F82"})}, {"color", in_spaces(s.f82_tint, a.f82_tint)}},
                                      {{"format", Json::array({"Gulbrandsen"})},
                                       {"color", in_spaces(s.edge_tint, a.edge_tint)}}})},
                        {"roughness", 0},
                        {"complexIor", Json::array({complex_ior("srgb-linear", s), complex_ior("acescg", a)})},
                        {"category", Json::array({"Metal"})},
                        {"references", references(r)}});
    }
    return {{"header",
             {{"schemaVersion", 2.1},
              {"license", licence},
              {"origin", std::string("metalfit ") + METALFIT_VERSION + " table"}}},
            {"data", data}};
}

}  // namespace metalfit
