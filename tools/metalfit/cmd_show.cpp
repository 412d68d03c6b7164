// metalfit show: the reference reflectance curve of one material at a few angles.
#include <cstdio>
#include <sstream>

#include "colour_options.hpp"
#include "commands.hpp"
#include "libfit/base/text.hpp"
#include "libfit/io/catalog.hpp"
#include "libfit/reference/reference_curve.hpp"
#include "libfit/reference/reflectance_summary.hpp"

namespace metalfit::cli {
namespace {

struct ShowOptions {
    std::string material;
    std::string source;
    UserFileLabels labels;
    ColourOptions colour;
    bool json = false;
    std::filesystem::path output;
};

void run_show(const ShowOptions& o, const GlobalOptions& global) {
    const Catalog catalog = Catalog::load(global.data_dir);
    const Material material = load_material(catalog, o.material, o.source, o.labels);
    for (const auto& w : material.warnings) warn(w);

    const ColourSetup setup = resolve_colour_options(o.colour, global);
    const auto& config = setup.config;
    const auto& colorimetry = setup.colorimetry;
    const ReferenceCurve curve(material, colorimetry, setup.converter, setup.spectral);

    const ReflectanceSummary summary = summarize_reflectance(curve);
    if (o.json) {
        emit(reflectance_record(material, curve, summary, colorimetry, config, setup.spectral).dump(2) + "\n", o.output);
        return;
    }
    const std::vector<ReflectanceSample>& samples = summary.samples;
    const WavelengthRange range = material.index.range();
    const RGB white = curve.raw_white();
    std::ostringstream s;
    s << material.name << " (" << material.id << "), source " << material.source << "\n"
      << "  file        " << material.provenance.file.string() << "\n"
      << "  sha256      " << material.provenance.sha256 << "\n"
      << "  reference   " << one_line(material.provenance.references) << "\n"
      << (material.provenance.note.empty() ? "" : "  caveat      " + material.provenance.note + "\n")
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
    for (const OutOfGamutValue& g : summary.out_of_gamut)
        s << "  out of gamut: " << g.quantity << " " << "RGB"[g.channel] << " = " << fixed(g.value) << " (kept, not clipped)\n";
    emit(s.str(), o.output);
}

}  // namespace

std::function<void()> add_show_command(CLI::App& app, const GlobalOptions& global) {
    auto o = std::make_shared<ShowOptions>();
    app.add_option("material", o->material, "Catalog material (id, name or alias) or a .yml/.csv/.tsv/.txt/.dat file")->required();
    app.add_option("--source", o->source, "Alternate source of a catalog material (default: its primary)");
    app.add_option("--name", o->labels.name, "Name of the material in a file of your own (default: the file stem)");
    app.add_option("--reference", o->labels.reference,
                   "Literature reference of a file of your own, shown and exported (default: the file's REFERENCES)");
    add_colour_options(app, o->colour);
    app.add_flag("--json", o->json, "Print one JSON object");
    app.add_option("-o,--output", o->output, "Write to this file instead of stdout");
    return [o, &global] { run_show(*o, global); };
}

}  // namespace metalfit::cli
