// metalfit export: fitted (or closed-form) parameters written as JSON, GLSL, HLSL, MaterialX, OpenPBR and C++ files
// (docs/export.md). Parses the options and calls libfit's export_files and write_export.
#include <algorithm>
#include <thread>

#include "colour_options.hpp"
#include "commands.hpp"
#include "progress.hpp"
#include "libfit/io/catalog.hpp"
#include "libfit/base/errors.hpp"
#include "libfit/export/export.hpp"

namespace metalfit::cli {
namespace {

struct ExportOptions {
    std::string material;
    bool all = false;
    std::string source;
    UserFileLabels labels;
    std::string models;
    std::string params = "fit";
    std::string formats;
    std::string gamut = "keep";
    ColourOptions colour;
    int jobs = 0;  // 0: all cores
    std::filesystem::path output;
};

void run_export(const ExportOptions& o, const GlobalOptions& global) {
    if (!o.all && o.material.empty()) throw UsageError("export: give a material (catalog name or file), or --all");
    if (o.all && !o.material.empty()) throw UsageError("export: give a material or --all, not both");
    if (o.all && !o.source.empty()) throw UsageError("export: --source needs a single material");
    // Every argument is checked before any work, so that a usage error costs nothing and writes nothing.
    const ExportRequest request{parse_export_formats(o.formats), parse_model_list(o.models), parse_parameter_source(o.params),
                                parse_gamut_policy(o.gamut)};
    const Catalog catalog = Catalog::load(global.data_dir);
    const auto loaders = material_loaders(catalog, o.all, o.material, o.source, o.labels);
    const ColourSetup setup = resolve_colour_options(o.colour, global);
    const ErrorSettings error{};  // the defaults of `metalfit fit`: rel metric, uniform weight, 128 nodes
    const MaterialFitRequest fit_request{setup.spectral, error, models_to_fit(request)};
    const int jobs = o.jobs > 0 ? o.jobs : static_cast<int>(std::max(1u, std::thread::hardware_concurrency()));
    TerminalProgress progress;
    const std::vector<MaterialFit> fits = fit_materials(loaders, setup.batch(), fit_request, jobs, progress.callback());
    for (const MaterialFit& f : fits)
        for (const auto& w : f.material.warnings) warn(f.material.id + ": " + w);
    const FitRecordContext context{setup.config, setup.converter.space(), setup.colorimetry.observer(),
                                   setup.colorimetry.illuminant(), setup.spectral, error};
    write_export(o.output, export_files(fits, context, request));
}

}  // namespace

std::function<void()> add_export_command(CLI::App& app, const GlobalOptions& global) {
    auto o = std::make_shared<ExportOptions>();
    app.add_option("material", o->material, "Catalog material (id, name or alias) or a .yml/.csv/.tsv/.txt/.dat file");
    app.add_flag("--all", o->all, "Every material of the built-in catalog, in parallel");
    app.add_option("--source", o->source, "Alternate source of a catalog material (default: its primary)");
    app.add_option("--name", o->labels.name, "Name of the material in a file of your own (default: the file stem)");
    app.add_option("--reference", o->labels.reference,
                   "Literature reference of a file of your own, shown and exported (default: the file's REFERENCES)");
    app.add_option("--model", o->models, "Models, comma-separated, or all")->required();
    // --params and --gamut are checked by libfit's parsers: one line naming the value, like every other error.
    app.add_option("--params", o->params, "Parameters written: fit (Ceres) or closed (best closed form)");
    app.add_option("--format", o->formats, "Formats, comma-separated, or all: json, glsl, hlsl, mtlx, openpbr, cpp")->required();
    app.add_option("--gamut", o->gamut, "Colour parameters outside [0, 1]: keep (flagged), clip, or scale by 1/max");
    add_colour_options(app, o->colour);
    app.add_option("-j,--jobs", o->jobs, "Threads for --all (default: all cores)")->check(CLI::NonNegativeNumber);
    app.add_option("-o,--output", o->output, "Output directory (created if missing)")->required();
    return [o, &global] { run_export(*o, global); };
}

}  // namespace metalfit::cli
