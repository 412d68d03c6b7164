#include "libfit/fit/metal_table.hpp"

#include <algorithm>
#include <cstdio>
#include <sstream>

#include "libfit/base/number_text.hpp"
#include "libfit/base/text.hpp"
#include "libfit/base/version.hpp"
#include "libfit/io/layer_stack.hpp"
#include "libfit/models/schlick/schlick.hpp"

namespace metalfit {

namespace {

using Json = nlohmann::ordered_json;

// R(1/7) / Schlick(F0, 1/7) per channel: the f82-tint model's closed form (F82Tint::closed_forms).
RGB f82_tint(const RGB& f0, const RGB& f82) {
    RGB tint;
    for (int c = 0; c < 3; ++c) {
        const double f = f0[c];
        tint[c] = f82[c] / models::Schlick::evaluate(&f, kMuF82);
    }
    return tint;
}

std::string fixed4(double v) { return fixed_text(v, 4); }

bool in_gamut(const RGB& v) { return v.min() >= 0.0 && v.max() <= 1.0; }

std::string csv_field(const std::string& s) {  // RFC 4180: quote when needed, double the quotes
    if (s.find_first_of(",\"\n") == std::string::npos) return s;
    std::string out = "\"";
    for (char c : s) out += c == '"' ? std::string("\"\"") : std::string(1, c);
    return out + "\"";
}

std::string md_cell(const std::string& s) {
    std::string out;
    for (char c : s) out += c == '|' ? std::string("\\|") : std::string(1, c);
    return out;
}

}  // namespace

std::string hex(const Display8& rgb) {
    char text[8];
    std::snprintf(text, sizeof text, "#%02x%02x%02x", rgb[0], rgb[1], rgb[2]);
    return text;
}

MetalTable metal_table(const Catalog& catalog, const MetalTableColour& colour) {
    std::vector<std::function<Material()>> loaders;
    for (const CatalogEntry& entry : catalog.entries())
        loaders.push_back([&catalog, id = entry.id] { return load_material(catalog, id); });
    return metal_table(loaders, catalog, colour);
}

MetalTable metal_table(const std::vector<std::function<Material()>>& loaders, const Catalog& catalog,
                       const MetalTableColour& colour) {
    MetalTable table{colour.working.space(), colour.display.description(), {}};
    std::vector<RGB> scene_values;  // F0 and tint of every row, in scene_linear, for one display call
    for (const auto& load : loaders) {
        const Material material = load();
        const ReferenceCurve working(material, colour.colorimetry, colour.working, colour.spectral);
        const ReferenceCurve scene(material, colour.colorimetry, colour.scene_linear, colour.spectral);
        // The catalog entry whose data file it is (a named finish's metal too), for its kind and reference.
        const CatalogEntry* entry = nullptr;
        bool in_catalog = false;
        for (const CatalogEntry& e : catalog.entries()) {
            if (e.primary.file == material.provenance.file) entry = &e, in_catalog = true;
            for (const CatalogSource& a : e.alternates)
                if (a.file == material.provenance.file) entry = &e;
            if (entry) break;
        }
        MetalTableRow row{material.id,
                          material.name,
                          entry ? entry->kind : "file",
                          material.source,
                          in_catalog ? entry->primary.reference : one_line(material.provenance.references),
                          material.provenance.note,
                          working(1.0),
                          {},
                          {},
                          {},
                          {},
                          nullptr};
        row.tint = f82_tint(row.f0, working(kMuF82));
        if (material.layers && !material.layers->empty()) {
            row.stack = describe_stack(material);
            row.stack_record = stack_record(material, catalog.data_dir());
        }
        const RGB scene_f0 = scene(1.0);
        scene_values.push_back(scene_f0);
        scene_values.push_back(f82_tint(scene_f0, scene(kMuF82)));
        table.rows.push_back(std::move(row));
    }
    const std::vector<Display8> display = display_colours(scene_values, colour.display);
    for (std::size_t i = 0; i < table.rows.size(); ++i) {
        table.rows[i].f0_display = display[2 * i];
        table.rows[i].tint_display = display[2 * i + 1];
    }
    return table;
}

std::string metal_table_csv(const MetalTable& table) {
    std::ostringstream s;
    const bool layered =
        std::any_of(table.rows.begin(), table.rows.end(), [](const auto& r) { return !r.stack.empty(); });
    s << "id,name,kind,F0_r,F0_g,F0_b,F0_hex,F0_r8,F0_g8,F0_b8,tint_r,tint_g,tint_b,tint_hex,tint_r8,tint_g8,tint_b8,"
         "in_gamut,source,reference,caveat"
      << (layered ? ",stack" : "") << "\n";
    for (const MetalTableRow& r : table.rows) {
        s << csv_field(r.id) << ',' << csv_field(r.name) << ',' << r.kind;
        for (const auto& [linear, display] : {std::pair{r.f0, r.f0_display}, std::pair{r.tint, r.tint_display}}) {
            for (int c = 0; c < 3; ++c) s << ',' << fixed4(linear[c]);
            s << ',' << hex(display);
            for (int c = 0; c < 3; ++c) s << ',' << static_cast<int>(display[static_cast<std::size_t>(c)]);
        }
        s << ',' << (in_gamut(r.f0) && in_gamut(r.tint) ? "yes" : "no") << ',' << csv_field(r.source) << ','
          << csv_field(r.reference) << ',' << csv_field(r.note);
        if (layered) s << ',' << csv_field(r.stack);
        s << '\n';
    }
    return s.str();
}

std::string metal_table_markdown(const MetalTable& table) {
    std::ostringstream s;
    s << "F0 = R(1) and F82 tint = R(1/7) / Schlick(F0, 1/7), linear " << table.space << "; hex and 8-bit through "
      << table.display << " (clamped to [0, 1]). `*`: a linear value outside [0, 1].\n\n";
    s << "| id | name | F0 (linear) | F0 hex | tint (linear) | tint hex | source | caveat |\n";
    s << "|---|---|---|---|---|---|---|---|\n";
    for (const MetalTableRow& r : table.rows) {
        const auto triple = [](const RGB& v) {
            return fixed4(v.r) + ", " + fixed4(v.g) + ", " + fixed4(v.b) + (in_gamut(v) ? "" : " *");
        };
        s << "| " << md_cell(r.id) << " | " << md_cell(r.name) << " | " << triple(r.f0) << " | `" << hex(r.f0_display)
          << "` | " << triple(r.tint) << " | `" << hex(r.tint_display) << "` | " << md_cell(r.source) << " ("
          << md_cell(r.reference) << ") | " << md_cell(r.note)
          << (r.stack.empty() ? "" : std::string(r.note.empty() ? "" : " ") + "stack: " + md_cell(r.stack)) << " |\n";
    }
    return s.str();
}

nlohmann::ordered_json metal_table_json(const MetalTable& table) {
    Json rows = Json::array();
    for (const MetalTableRow& r : table.rows) {
        const auto colour = [](const RGB& linear, const Display8& display) {
            return Json{{"linear", {linear.r, linear.g, linear.b}},
                        {"in_gamut", in_gamut(linear)},
                        {"display8", {display[0], display[1], display[2]}},
                        {"hex", hex(display)}};
        };
        rows.push_back({{"id", r.id},
                        {"name", r.name},
                        {"kind", r.kind},
                        {"F0", colour(r.f0, r.f0_display)},
                        {"F82_tint", colour(r.tint, r.tint_display)},
                        {"source", r.source},
                        {"reference", r.reference},
                        {"note", r.note}});
        if (!r.stack.empty()) rows.back()["stack"] = r.stack_record;
    }
    return {{"schema", "metalfit.table/1"},
            {"metalfit_version", METALFIT_VERSION},
            {"space", table.space},
            {"display", table.display},
            {"mu_f82", kMuF82},
            {"materials", rows}};
}

std::vector<Display8> display_colours(const std::vector<RGB>& linear, const DisplayTransform& display) {
    std::vector<float> pixels;
    for (const RGB& v : linear)
        for (int c = 0; c < 3; ++c) pixels.push_back(static_cast<float>(v[c]));
    const std::vector<unsigned char> bytes = display.apply(pixels, static_cast<int>(linear.size()), 1);
    std::vector<Display8> out(linear.size());
    for (std::size_t i = 0; i < linear.size(); ++i) out[i] = {bytes[3 * i], bytes[3 * i + 1], bytes[3 * i + 2]};
    return out;
}

}  // namespace metalfit
