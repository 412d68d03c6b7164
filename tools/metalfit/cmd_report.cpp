// metalfit report: the fits of one material or the catalog as a folder of pages, report.json and images
// (docs/report.md); --fail-above turns it into a gate for material libraries.

#include <algorithm>
#include <iostream>
#include <optional>
#include <thread>

#include "colour_options.hpp"
#include "commands.hpp"
#include "error_options.hpp"
#include "layer_options.hpp"
#include "libfit/base/errors.hpp"
#include "libfit/base/standard_output.hpp"
#include "libfit/color/display_transform.hpp"
#include "libfit/fit/budget.hpp"
#include "libfit/fit/fit_batch.hpp"
#include "libfit/fit/model_cost.hpp"
#include "libfit/io/catalog.hpp"
#include "libfit/report/fail_above.hpp"
#include "libfit/report/model_costs.hpp"
#include "libfit/report/report.hpp"
#include "libfit/report/report_stream.hpp"
#include "material_selection.hpp"
#include "progress.hpp"
#include "recommend_options.hpp"

namespace metalfit::cli {
namespace {

struct ReportOptions {
    MaterialSelection selection;
    LayerOptions layers;
    std::string models = "all";
    ColourOptions colour;
    ErrorOptions error;
    int jobs = 0;
    std::string renders = "auto";
    std::string sources = "all";
    std::string fail_above;
    std::string budget;
    std::string budget_metric = "rel_rms";
    std::filesystem::path costs;
    std::filesystem::path output;
    RecommendOptions recommend{true};  // always: each page opens with it, the heat map marks it
};

void run_report(const ReportOptions& o, const GlobalOptions& global) {
    const RenderMode render_mode = parse_render_mode(o.renders);
    const double fail_above =
        o.fail_above.empty() ? 0.0 : parse_relative_limit(o.fail_above, "--fail-above");  // 0: no gate
    std::optional<Budget> budget;
    if (!o.budget.empty()) budget = parse_budget(o.budget, parse_budget_metric(o.budget_metric));
    const CostTable cost_table =
        o.costs.empty() ? builtin_cost_table() : cost_table_from_bench_json(o.costs, global.data_dir);
    const Tolerance tolerance = *o.recommend.tolerance();
    const ExportFormat target = o.recommend.target_format();
    check_report_folder(o.output);  // before the fits, which take a while for --all
    const Catalog catalog = Catalog::load(global.data_dir);
    const auto selected = o.selection.loaders(catalog, "report");

    const ColourSetup setup = resolve_colour_options(o.colour, global);
    const auto loaders = o.layers.over(selected, global.data_dir, setup.spectral);
    const DisplayTransform display = DisplayTransform::create(setup.config);
    const ErrorSettings error = o.error.settings();
    FitConstraints constraints;
    o.recommend.constrain(constraints);  // the fits hold the recommendation's F0 error
    const MaterialFitRequest request{setup.spectral, error, parse_model_list(o.models), constraints};
    const int jobs = o.jobs > 0 ? o.jobs : static_cast<int>(std::max(1u, std::thread::hardware_concurrency()));
    // glpreview renders every material as the report fits it — a catalog material from its primary source, a named
    // finish, a file of the user's (as they named it, relative to the current folder, where glpreview runs too),
    // with --film/--coat over each — a column group per model of the report. A catalog material fitted from another
    // source (--source) is left out: the sheet renders primary sources. The renders come first, each material
    // loaded to see its id and source, so that each material's entry can be written as its fit arrives.
    SphereRenders renders{std::nullopt, "--renders off"};
    if (render_mode != RenderMode::off) {
        SphereRenderRequest render_request{glpreview_beside_this_program(),
                                           global.data_dir / "scenes" / "sheet.json",
                                           {},
                                           {},
                                           o.layers.film,
                                           o.layers.coat,
                                           {},
                                           global.data_dir,
                                           setup.config};
        for (const Model* m : request.models) render_request.models.emplace_back(m->id());
        std::vector<std::string> names;
        if (o.selection.all)
            for (const CatalogEntry& e : catalog.entries()) names.push_back(e.id);
        else
            names = o.selection.materials();
        for (std::size_t i = 0; i < loaders.size() && i < names.size(); ++i) {
            const Material material = loaders[i]();
            const CatalogEntry* e = catalog.find(names[i]);
            if (!e || e->primary.file == material.provenance.file) {
                render_request.materials.push_back(names[i]);
                render_request.ids.push_back(material.id);
            }
        }
        std::optional<TerminalProgress> render_progress;
        render_request.progress = render_progress.emplace("metalfit report: renders").callback();
        renders = render_spheres(render_request, render_mode);
        render_progress.reset();  // the line cleared before anything else is printed
        if (!renders.rows && render_mode == RenderMode::auto_)
            std::cerr << "metalfit: renders skipped: " << renders.skipped << "\n";
    }

    FitRecordContext context = setup.record_context(error);
    context.constraints = constraints;
    // The costs and the budget; each material's choice and recommendation are made as its fit arrives.
    const CostAndBudget cost = report_costs({}, cost_table, budget);
    const ReportInputs inputs{context, setup.colorimetry, setup.converter,   display, catalog,
                              cost,    renders,           o.sources == "all"};
    // Streamed: each material's page and record entry are written as its fit arrives and the fit let go
    // (docs/decisions.md, "Streamed export and report"); the folder is switched in as one unit at the end.
    ReportStream stream(o.output, inputs, cost_table, budget, tolerance, target);
    std::vector<std::string> warnings, above;
    {
        TerminalProgress progress("metalfit report: fits");
        fit_materials_in_order(
            loaders, setup.batch(), request, jobs,
            [&](std::size_t, MaterialFit&& fit) {
                for (const auto& w : fit.material.warnings) warnings.push_back(fit.material.id + ": " + w);
                if (fail_above > 0)
                    for (std::string& line : channels_above(fit, fail_above)) above.push_back(std::move(line));
                stream.add(fit);
            },
            progress.callback());
    }
    for (const std::string& w : warnings) warn(w);
    std::cout << (o.output / "index.html").string() << "\n";
    flush_standard_output();  // a stdout that fails: nothing written
    stream.finish();

    if (fail_above > 0) {
        for (const std::string& line : above) std::cerr << "metalfit: above --fail-above: " << line << "\n";
        if (!above.empty()) throw FailAbove{above.size()};
    }
}

}  // namespace

std::function<void()> add_report_command(CLI::App& app, const GlobalOptions& global) {
    auto o = std::make_shared<ReportOptions>();
    o->selection.add_options(app, true);
    o->layers.add_options(app);
    app.add_option("--model", o->models, "Models, comma-separated, or all: " + model_ids());
    add_colour_options(app, o->colour);
    add_error_options(app, o->error);
    app.add_option("-j,--jobs", o->jobs, "Threads for --all (default: all cores)")->check(CLI::NonNegativeNumber);
    app.add_option(
        "--renders", o->renders,
        "Sphere renders through glpreview: auto (skip, saying why, when they cannot be made), on (fail then), off");
    app.add_option("--sources", o->sources,
                   "Data sources of a catalog material: all (F0 and F82 of every measurement the catalog holds, their "
                   "spread next to each model's error) or primary (only the one fitted)")
        ->check(CLI::IsMember({"all", "primary"}))
        ->capture_default_str();
    app.add_option("--fail-above", o->fail_above,
                   "After writing the report, exit with code 6 and one line per material/model/channel whose fitted "
                   "rel_rms is above REL (0.005 or 0.5%)");
    app.add_option("--budget", o->budget,
                   "Mark per material the cheapest model whose fit meets this error in every channel (0.5% or 0.005)");
    app.add_option("--budget-metric", o->budget_metric, "Metric of --budget: rel_rms, max_rel, f0_err or de2000_max");
    app.add_option("--costs", o->costs,
                   "Cost table: a `metalfit bench --json` report (default: the built-in llvmpipe ratios)");
    add_recommend_options(app, o->recommend, false);
    app.add_option("-o,--output", o->output, "Report folder (written as a whole; replaced if it exists)")->required();
    return [o, &global] { run_report(*o, global); };
}

}  // namespace metalfit::cli
