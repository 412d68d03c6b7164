// metalfit show: the reference reflectance curve of one material at a few angles.
#include <nlohmann/json.hpp>

#include <cstdio>
#include <sstream>

#include "colour_options.hpp"
#include "commands.hpp"
#include "libfit/io/catalog.hpp"
#include "libfit/reference/reference_curve.hpp"
#include "libfit/base/version.hpp"

namespace metalfit::cli {
namespace {

struct ShowOptions {
    std::string material;
    std::string source;
    ColourOptions colour;
    bool json = false;
    std::filesystem::path output;
};

struct Sample {
    std::string label;  // "F0", "F82", "R(0.5)"
    double mu;
    RGB value;
};

constexpr const char* kChannels[] = {"R", "G", "B"};

nlohmann::json rgb_json(const RGB& c) { return nlohmann::json::array({c.r, c.g, c.b}); }

// REFERENCES as one line of plain text: refractiveindex.info writes HTML over several lines.
std::string one_line(const std::string& text) {
    std::string out;
    bool in_tag = false, space = false;
    for (char c : text) {
        if (c == '<') in_tag = true;
        else if (c == '>') in_tag = false;
        else if (!in_tag && (c == '\n' || c == ' ' || c == '\t')) space = !out.empty();
        else if (!in_tag) {
            if (space) out += ' ';
            out += c;
            space = false;
        }
    }
    return out;
}

void run_show(const ShowOptions& o, const GlobalOptions& global) {
    const Catalog catalog = Catalog::load(global.data_dir);
    const Material material = load_material(catalog, o.material, o.source);
    for (const auto& w : material.warnings) warn(w);

    const ColourSetup setup = resolve_colour_options(o.colour, global);
    const auto& config = setup.config;
    const auto& colorimetry = setup.colorimetry;
    const ReferenceCurve curve(material, colorimetry, setup.converter, setup.spectral);

    const std::vector<Sample> samples = {{"F0", 1.0, curve(1.0)},
                                         {"F82", kMuF82, curve(kMuF82)},
                                         {"R(0.5)", 0.5, curve(0.5)},
                                         {"R(0.25)", 0.25, curve(0.25)},
                                         {"R(0.1)", 0.1, curve(0.1)}};
    nlohmann::json out_of_gamut = nlohmann::json::array();
    for (const auto& s : samples)
        for (int c = 0; c < 3; ++c)
            if (s.value[c] > 1.0 || s.value[c] < 0.0)
                out_of_gamut.push_back({{"quantity", s.label}, {"channel", kChannels[c]}, {"value", s.value[c]}});

    const WavelengthRange range = material.index.range();
    const RGB white = curve.raw_white();
    if (o.json) {
        nlohmann::json j;
        j["schema"] = "metalfit.show/1";
        j["material"] = material.id;
        j["name"] = material.name;
        j["source"] = material.source;
        j["space"] = curve.converter().space();
        j["F0"] = rgb_json(samples[0].value);
        j["F82"] = rgb_json(samples[1].value);
        j["R"] = {{"0.5", rgb_json(samples[2].value)}, {"0.25", rgb_json(samples[3].value)}, {"0.1", rgb_json(samples[4].value)}};
        j["out_of_gamut"] = out_of_gamut;
        j["provenance"] = {{"file", material.provenance.file.string()},
                           {"sha256", material.provenance.sha256},
                           {"format", material.provenance.format},
                           {"data_type", material.provenance.data_type},
                           {"reference", material.provenance.references},
                           {"conditions", material.provenance.conditions},
                           {"range_nm", {range.min_nm, range.max_nm}},
                           {"points_360_830", material.index.n.tabulated_points_in(kVisibleRange)},
                           {"cmf", to_string(colorimetry.observer())},
                           {"illuminant", to_string(colorimetry.illuminant())},
                           {"interpolation", o.colour.interpolation},
                           {"extrapolate", o.colour.extrapolate},
                           {"ocio_config", config.path.string()},
                           {"ocio_config_origin", config.origin},
                           {"white_raw_rgb", rgb_json(white)},
                           {"metalfit_version", METALFIT_VERSION}};
        j["warnings"] = material.warnings;
        emit(j.dump(2) + "\n", o.output);
        return;
    }
    std::ostringstream s;
    s << material.name << " (" << material.id << "), source " << material.source << "\n"
      << "  file        " << material.provenance.file.string() << "\n"
      << "  sha256      " << material.provenance.sha256 << "\n"
      << "  reference   " << one_line(material.provenance.references) << "\n"
      << "  data        " << material.provenance.data_type << ", " << fixed(range.min_nm, 1) << "–"
      << fixed(range.max_nm, 1) << " nm, "
      << (material.index.n.tabulated() ? std::to_string(material.index.n.tabulated_points_in(kVisibleRange)) +
                                             " points in 360–830 nm, " + o.colour.interpolation + " interpolation"
                                       : std::string("analytic n"))
      << "\n"
      << "  colour      " << to_string(colorimetry.observer()) << ", " << to_string(colorimetry.illuminant()) << ", "
      << curve.converter().space() << " (" << config.path.string() << ", " << config.origin << ")\n"
      << "  white       raw perfect reflector (" << fixed(white.r, 6) << ", " << fixed(white.g, 6) << ", "
      << fixed(white.b, 6) << "); curves are divided by it\n\n"
      << "              mu         R         G         B\n";
    for (const auto& sample : samples) {
        s << "  " << sample.label << std::string(10 - sample.label.size(), ' ') << fixed(sample.mu, 4);
        for (int c = 0; c < 3; ++c) s << "  " << (sample.value[c] < 0 ? "" : " ") << fixed(sample.value[c]);
        s << "\n";
    }
    for (const auto& g : out_of_gamut)
        s << "  out of gamut: " << g["quantity"].get<std::string>() << " " << g["channel"].get<std::string>() << " = "
          << fixed(g["value"].get<double>()) << " (kept, not clipped)\n";
    emit(s.str(), o.output);
}

}  // namespace

std::function<void()> add_show_command(CLI::App& app, const GlobalOptions& global) {
    auto o = std::make_shared<ShowOptions>();
    app.add_option("material", o->material, "Catalog material (id, name or alias) or a .yml/.csv file")->required();
    app.add_option("--source", o->source, "Alternate source of a catalog material (default: its primary)");
    add_colour_options(app, o->colour);
    app.add_flag("--json", o->json, "Print one JSON object");
    app.add_option("-o,--output", o->output, "Write to this file instead of stdout");
    return [o, &global] { run_show(*o, global); };
}

}  // namespace metalfit::cli
