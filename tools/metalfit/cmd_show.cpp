// metalfit show: the reference reflectance curve of one material at a few angles.
#include <algorithm>
#include <cmath>
#include <cstdio>
#include <numbers>
#include <sstream>

#include "colour_options.hpp"
#include "commands.hpp"
#include "layer_options.hpp"
#include "libfit/base/text.hpp"
#include "libfit/io/catalog.hpp"
#include "libfit/io/layer_stack.hpp"
#include "libfit/reference/reference_curve.hpp"
#include "libfit/reference/reflectance_summary.hpp"
#include "material_selection.hpp"

namespace metalfit::cli {
namespace {

struct ShowOptions {
    MaterialSelection selection;
    LayerOptions layers;
    ColourOptions colour;
    bool json = false;
    std::filesystem::path output;
};

std::string held_constant_lines(const ReferenceCurve& curve) {
    std::string lines;
    for (const std::string& note : curve.held_constant()) lines += "  held        " + note + "\n";
    return lines;
}

// The human-readable summary of one material.
std::string show_text(const Material& material, const ReferenceCurve& curve, const ReflectanceSummary& summary,
                      const ColourSetup& setup, const ShowOptions& o) {
    const auto& config = setup.config;
    const auto& colorimetry = setup.colorimetry;
    const std::vector<ReflectanceSample>& samples = summary.samples;
    const WavelengthRange range = material.index.range();
    const RGB white = curve.raw_white();
    std::ostringstream s;
    s << material.name << " (" << material.id << "), source " << material.source << "\n"
      << "  file        " << material.provenance.file.string() << "\n"
      << "  sha256      " << material.provenance.sha256 << "\n"
      << "  reference   " << one_line(material.provenance.references) << "\n"
      << (material.provenance.note.empty() ? "" : "  caveat      " + material.provenance.note + "\n")
      << (material.layers ? "  stack       " + describe_stack(material) + "\n" : "") << "  data        "
      << material.provenance.data_type << ", " << fixed(range.min_nm, 1) << "–" << fixed(range.max_nm, 1) << " nm, "
      << (material.index.n.tabulated() ? std::to_string(material.index.n.tabulated_points_in(kVisibleRange)) +
                                             " points in 360–830 nm, " + o.colour.interpolation + " interpolation"
                                       : std::string("analytic n"))
      << "\n"
      << "  colour      " << to_string(colorimetry.observer()) << ", " << to_string(colorimetry.illuminant()) << ", "
      << curve.converter().space() << " (" << config.path.string() << ", " << config.origin << ")\n"
      << "  adaptation  "
      << describe_adaptation(colorimetry.adaptation(), colorimetry.adapted(), colorimetry.illuminant())
      << "; convention " << to_string(setup.convention) << "\n"
      << held_constant_lines(curve) << "  white       raw perfect reflector (" << fixed(white.r, 6) << ", "
      << fixed(white.g, 6) << ", " << fixed(white.b, 6) << "); curves are divided by it\n\n"
      << "  reflectance as a fraction of 1; mu = cos θ, θ in degrees from the normal\n"
      << "                mu    θ deg            R         G         B\n";
    for (const auto& sample : samples) {
        const double theta_deg = std::acos(std::clamp(sample.mu, 0.0, 1.0)) * 180.0 / std::numbers::pi;
        s << "  " << sample.label << std::string(10 - sample.label.size(), ' ') << fixed(sample.mu, 4) << "    "
          << (theta_deg < 10 ? " " : "") << fixed(theta_deg, 2) << "   ";
        for (int c = 0; c < 3; ++c) s << "  " << (sample.value[c] < 0 ? "" : " ") << fixed(sample.value[c]);
        s << "\n";
    }
    for (const OutOfGamutValue& g : summary.out_of_gamut)
        s << "  out of gamut: " << g.quantity << " "
          << "RGB"[g.channel] << " = " << fixed(g.value) << " (kept, not clipped)\n";
    return s.str();
}

void run_show(const ShowOptions& o, const GlobalOptions& global) {
    const Catalog catalog = Catalog::load(global.data_dir);
    const auto selected = o.selection.loaders(catalog, "show");
    const ColourSetup setup = resolve_colour_options(o.colour, global);
    const auto loaders = o.layers.over(selected, global.data_dir, setup.spectral);
    std::string text;
    nlohmann::json records = nlohmann::json::array();
    for (const auto& load : loaders) {
        const Material material = load();
        for (const auto& w : material.warnings) warn(loaders.size() > 1 ? material.id + ": " + w : w);
        const ReferenceCurve curve(material, setup.colorimetry, setup.converter, setup.spectral);
        for (const auto& w : curve.held_constant()) warn(loaders.size() > 1 ? material.id + ": " + w : w);
        const ReflectanceSummary summary = summarize_reflectance(curve);
        if (o.json)
            records.push_back(reflectance_record(material, curve, summary, setup.colorimetry, setup.config,
                                                 setup.spectral, global.data_dir, setup.convention));
        else
            text += (text.empty() ? "" : "\n") + show_text(material, curve, summary, setup, o);
    }
    // One material: its record; several (or --all): an array of records.
    if (o.json)
        emit((loaders.size() == 1 && !o.selection.all ? records.front() : records).dump(2) + "\n", o.output);
    else
        emit(text, o.output);
}

}  // namespace

std::function<void()> add_show_command(CLI::App& app, const GlobalOptions& global) {
    auto o = std::make_shared<ShowOptions>();
    o->selection.add_options(app, true);
    o->layers.add_options(app);
    add_colour_options(app, o->colour);
    app.add_flag("--json", o->json, "Print one JSON object (an array of them for several materials or --all)");
    app.add_option("-o,--output", o->output, "Write to this file instead of stdout (- for stdout)");
    return [o, &global] { run_show(*o, global); };
}

}  // namespace metalfit::cli
