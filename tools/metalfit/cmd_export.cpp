// metalfit export: fitted (or closed-form) parameters written as JSON, GLSL, HLSL, MaterialX, OpenPBR and C++ files
// (docs/export.md). Parses the options and calls libfit's export_files and write_export.
#include <algorithm>
#include <optional>
#include <string_view>
#include <thread>

#include "colour_options.hpp"
#include "commands.hpp"
#include "export_options.hpp"
#include "layer_options.hpp"
#include "libfit/base/errors.hpp"
#include "libfit/export/export.hpp"
#include "libfit/export/export_stream.hpp"
#include "libfit/fit/budget.hpp"
#include "libfit/fit/model_cost.hpp"
#include "libfit/io/catalog.hpp"
#include "material_selection.hpp"
#include "progress.hpp"

namespace metalfit::cli {
namespace {

struct ExportOptions {
    MaterialSelection selection;
    LayerOptions layers;
    std::string models;
    std::string params = "fit";
    std::string formats;
    std::string gamut = "keep";
    bool gamut_fit = false;
    std::string roughness;  // empty: kDefaultRoughness
    std::string id_prefix = kDefaultIdPrefix;
    ColourOptions colour;
    int jobs = 0;  // 0: all cores
    std::filesystem::path output;
    std::string budget_metric = "rel_rms";  // for --model best:BUDGET
    std::filesystem::path costs;
};

constexpr std::string_view kBest = "best:";

void run_export(const ExportOptions& o, const GlobalOptions& global) {
    // Every argument is checked before any work, so that a usage error costs nothing and writes nothing.
    // --model best:BUDGET: every model is fitted, and the cheapest that meets the budget is exported (libfit/fit/budget).
    const bool best = o.models.rfind(kBest, 0) == 0;
    std::optional<Budget> budget;
    if (best) {
        if (o.selection.all || o.selection.materials().size() > 1)
            throw UsageError("export: --model best:BUDGET chooses a model per material: give one material");
        budget = parse_budget(o.models.substr(kBest.size()), parse_budget_metric(o.budget_metric));
    } else if (!o.costs.empty()) {
        throw UsageError("export: --costs needs --model best:BUDGET");
    }
    ExportRequest request{parse_export_formats(o.formats),
                          best ? parse_model_list("all") : parse_model_list(o.models),
                          parse_parameter_source(o.params),
                          parse_gamut_policy(o.gamut),
                          o.roughness.empty() ? kDefaultRoughness : parse_roughness(o.roughness),
                          parse_id_prefix(o.id_prefix)};
    const CostTable costs =
        o.costs.empty() ? builtin_cost_table() : cost_table_from_bench_json(o.costs, global.data_dir);
    const Catalog catalog = Catalog::load(global.data_dir);
    const auto selected = o.selection.loaders(catalog, "export");
    const ColourSetup setup = resolve_colour_options(o.colour, global);
    const auto loaders = o.layers.over(selected, global.data_dir, setup.spectral);
    const ErrorSettings error{};  // the defaults of `metalfit fit`: rel metric, uniform weight, 128 nodes
    FitConstraints constraints;
    constraints.gamut_fit = o.gamut_fit;
    const MaterialFitRequest fit_request{setup.spectral, error, models_to_fit(request), constraints};
    FitRecordContext context = setup.record_context(error);
    context.constraints = constraints;
    const std::string materialx_space = materialx_colorspace(context.config, context.space);  // reads the config once
    if (o.formats == "all")
        if (const std::string left_out =
                leave_out_formats_the_space_cannot_carry(request, context.space, materialx_space);
            !left_out.empty())
            warn(left_out);
    require_export_space(request, context.space, materialx_space);  // glTF: Linear Rec.709 only, refused before fitting
    const int jobs = o.jobs > 0 ? o.jobs : static_cast<int>(std::max(1u, std::thread::hardware_concurrency()));
    TerminalProgress progress;
    if (!budget) {
        // Streamed: each material's files are staged as its fit arrives and the fit let go (docs/decisions.md,
        // "Streamed export and report"); the folder is switched in as one unit at the end, as write_export does.
        ExportStream stream(o.output, context, request, materialx_space);
        std::vector<std::string> warnings;
        fit_materials_for_export(
            loaders, setup.batch(), fit_request, request, jobs,
            [&](std::size_t, MaterialFit&& fit) {
                for (const auto& w : fit.material.warnings) warnings.push_back(fit.material.id + ": " + w);
                for (std::string& w : refusal_warnings(fit)) warnings.push_back(std::move(w));
                stream.add(fit);
            },
            progress.callback());
        for (const std::string& w : warnings) warn(w);
        for (const std::string& w : export_warnings(context, request, materialx_space)) warn(w);
        // After the folder is in place: a refused or failed write stays one line, about what was not written.
        stream.finish([](const std::string& line) { warn(line); });
        return;
    }
    std::vector<MaterialFit> fits = fit_materials(loaders, setup.batch(), fit_request, jobs, progress.callback());
    // OpenPBR, MaterialX and glTF write a layered material as their own coat / thin film over the bare metal.
    if (needs_bare_metal_fits(request)) attach_bare_metal_fits(fits, setup.batch(), fit_request, jobs);
    for (const MaterialFit& f : fits) {
        for (const auto& w : f.material.warnings) warn(f.material.id + ": " + w);
        for (const std::string& w : refusal_warnings(f)) warn(w);
    }
    for (const std::string& w : export_warnings(context, request, materialx_space)) warn(w);
    const BudgetChoice choice = choose_model(fits.front().models, costs, *budget);
    if (!choice.chosen)
        throw UsageError(fits.front().material.id + ": no model meets " + budget_text(*budget) + " in every channel (" +
                         choice.summary() + "; cost table: " + choice.cost_source + ")");
    warn(fits.front().material.id + ": --model best:" + o.models.substr(kBest.size()) + " chose " + choice.summary() +
         "; cost table: " + choice.cost_source);
    request.models = {choice.chosen};
    const std::vector<ExportFile> files = export_files(fits, context, request, materialx_space);
    write_export(o.output, files);
    // After the folder is in place: a refused or failed write stays one line, about what was not written.
    for (const std::string& line : out_of_range_lines(files)) warn(line);
}

}  // namespace

std::function<void()> add_export_command(CLI::App& app, const GlobalOptions& global) {
    auto o = std::make_shared<ExportOptions>();
    o->selection.add_options(app, true);
    o->layers.add_options(app);
    app.add_option("--model", o->models,
                   "Models, comma-separated, or all (" + model_ids() +
                       "), or best:BUDGET (e.g. best:0.5%: the cheapest model meeting that error in every channel)")
        ->required();
    app.add_option("--budget-metric", o->budget_metric,
                   "Metric of --model best:BUDGET: rel_rms, max_rel, f0_err or de2000_max");
    app.add_option("--costs", o->costs,
                   "Cost table for --model best:BUDGET: a `metalfit bench --json` report (default: built-in llvmpipe "
                   "ratios)");
    // --params and --gamut are checked by libfit's parsers: one line naming the value, like every other error.
    app.add_option("--params", o->params, "Parameters written: fit (Ceres) or closed (best closed form)");
    app.add_option("--format", o->formats, "Formats, comma-separated, or all: " + export_format_list())->required();
    app.add_option("--gamut", o->gamut, "Colour parameters outside [0, 1]: keep (flagged), clip, or scale by 1/max");
    app.add_flag(
        "--gamut-fit", o->gamut_fit,
        "Fit every channel's curve inside [0, 1] at every angle (constrained, so --gamut has nothing left to do)");
    app.add_option("--roughness", o->roughness,
                   "Surface roughness R in [0, 1] written with the Fresnel parameters (MaterialX, OpenPBR, JSON; "
                   "OpenPBR's specular_roughness, MaterialX alpha = R^2); default " +
                       std::string(kDefaultRoughnessText));
    app.add_option("--id-prefix", o->id_prefix,
                   "Prefix of every per-material identifier and file (<prefix>_<material>_<model>, <prefix>_materials; "
                   "the shared model functions keep theirs): [a-z][a-z0-9_]{0,30}");
    add_colour_options(app, o->colour);
    app.add_option("-j,--jobs", o->jobs, "Threads for --all (default: all cores)")->check(CLI::NonNegativeNumber);
    app.add_option("-o,--output", o->output, "Output directory (created if missing)")->required();
    return [o, &global] { run_export(*o, global); };
}

}  // namespace metalfit::cli
