// metalfit table: F0 and F82 tint of every catalog metal (or of the materials named, under --film/--coat when given),
// linear and as 8-bit display values / hex, with the source and caveat (libfit's metal_table), as CSV, JSON or
// Markdown; or, in srgb-linear and ACEScg at once, in physicallybased.info's material shape (libfit's
// physicallybased_table); or, with --recommend, the recommended model of each material (libfit's
// export/recommendation).
#include <nlohmann/json.hpp>

#include <algorithm>
#include <thread>

#include "colour_options.hpp"
#include "commands.hpp"
#include "error_options.hpp"
#include "layer_options.hpp"
#include "libfit/base/errors.hpp"
#include "libfit/export/recommendation.hpp"
#include "libfit/fit/fit_batch.hpp"
#include "libfit/fit/metal_table.hpp"
#include "libfit/fit/model_cost.hpp"
#include "libfit/fit/oxide_chart.hpp"
#include "libfit/fit/physicallybased_table.hpp"
#include "libfit/fit/renderer_film_scores.hpp"
#include "material_selection.hpp"
#include "recommend_options.hpp"

namespace metalfit::cli {
namespace {

struct TableOptions {
    MaterialSelection selection;
    LayerOptions layers;
    ColourOptions colour;
    std::string format = "md";
    RecommendOptions recommend;   // --recommend: the recommended model per material instead of F0 and F82 tint
    std::filesystem::path costs;  // --costs of --recommend
    std::filesystem::path output;
    std::string thickness;   // --thickness FIRST:LAST:STEP: the oxide chart
    std::string versus;      // --versus INDEX
    bool renderers = false;  // --renderers: the renderers' thin films scored instead of the chart
};

// `table METAL --film FILM --thickness A:B:Cnm --renderers`: what each renderer's thin-film approximation draws,
// scored against the stack's curve (libfit's renderer_film_scores).
void run_renderer_scores(const TableOptions& o, const GlobalOptions& global, const Catalog& catalog,
                         const ColourSetup& setup) {
    if (o.format != "md" && o.format != "csv" && o.format != "json")
        throw UsageError("--renderers: the scores' formats are md, csv and json");
    if (!o.versus.empty()) throw UsageError("--renderers scores the film itself: no --versus");
    if (!o.layers.coat.empty())
        throw UsageError("--renderers: a film in air (the renderers' film formulas take air above it): no --coat");
    const std::vector<double> thicknesses = parse_thickness_range(o.thickness);
    const auto selected = o.selection.loaders(catalog, "table --thickness");
    if (selected.size() != 1) throw UsageError("table --thickness: give one metal (Ti)");
    const LayerOptions::ChartLayers layers = o.layers.chart_layers(global.data_dir);
    Material metal = selected.front()();
    if (metal.layers && !metal.layers->empty())
        throw UsageError("table --thickness: " + metal.id +
                         " is a named finish with layers of its own: give its metal");
    for (const std::string& w : metal.warnings) warn(w);
    for (const std::string& w : layers.film.warnings) warn("film " + layers.film.id + ": " + w);
    const RendererFilmScores scores =
        renderer_film_scores({std::move(metal), layers.film, thicknesses, ErrorOptions{}.settings()}, setup.colorimetry,
                             setup.converter, setup.spectral);
    if (o.format == "csv")
        emit(renderer_film_scores_csv(scores), o.output);
    else if (o.format == "json")
        emit(renderer_film_scores_json(scores).dump(2) + "\n", o.output);
    else
        emit(renderer_film_scores_markdown(scores), o.output);
}

// `table METAL --film FILM --thickness 0:300:10nm [--versus 2.488]`: the oxide colour chart (libfit's oxide_chart).
void run_chart(const TableOptions& o, const GlobalOptions& global, const Catalog& catalog, const ColourSetup& setup) {
    if (o.format == "physicallybased") throw UsageError("--thickness: the chart's formats are md, csv, json and html");
    // Every argument is checked before any work.
    const std::vector<double> thicknesses = parse_thickness_range(o.thickness);
    const std::optional<double> versus =
        o.versus.empty() ? std::nullopt : std::optional<double>(parse_versus_index(o.versus));
    const auto selected = o.selection.loaders(catalog, "table --thickness");
    if (selected.size() != 1) throw UsageError("table --thickness: give one metal (Ti)");
    const LayerOptions::ChartLayers layers = o.layers.chart_layers(global.data_dir);
    Material metal = selected.front()();
    if (metal.layers && !metal.layers->empty())
        throw UsageError("table --thickness: " + metal.id +
                         " is a named finish with layers of its own: give its metal");
    for (const std::string& w : metal.warnings) warn(w);
    for (const std::string& w : layers.film.warnings) warn("film " + layers.film.id + ": " + w);
    const ColorSpaceConverter scene_linear = ColorSpaceConverter::create(setup.config);
    const DisplayTransform display = DisplayTransform::create(setup.config);
    const OxideChart chart =
        oxide_chart({std::move(metal), layers.film, layers.coat, thicknesses, versus, global.data_dir},
                    {setup.colorimetry, setup.converter, scene_linear, display, setup.spectral});
    if (o.format == "csv")
        emit(oxide_chart_csv(chart), o.output);
    else if (o.format == "json")
        emit(oxide_chart_json(chart).dump(2) + "\n", o.output);
    else if (o.format == "html")
        emit(oxide_chart_html(chart), o.output);
    else
        emit(oxide_chart_markdown(chart), o.output);
}

// `table --recommend`: every model fitted per material (under the tolerance's F0 constraint), the recommendation of
// each (libfit's export/recommendation).
void run_recommendations(const TableOptions& o, const GlobalOptions& global, const Catalog& catalog,
                         const ColourSetup& setup, bool every_metal) {
    const Tolerance tolerance = *o.recommend.tolerance();
    const ExportFormat target = o.recommend.target_format();
    const CostTable costs =
        o.costs.empty() ? builtin_cost_table() : cost_table_from_bench_json(o.costs, global.data_dir);
    FitConstraints constraints;
    o.recommend.constrain(constraints);
    const ErrorSettings error = ErrorOptions{}.settings();
    const MaterialFitRequest request{setup.spectral, error, parse_model_list("all"), constraints};
    const auto selected = every_metal ? material_loaders(catalog, true, {}, "", o.selection.labels)
                                      : o.selection.loaders(catalog, "table");
    const auto loaders = o.layers.over(selected, global.data_dir, setup.spectral);
    std::vector<Recommendation> rows;
    const int jobs = static_cast<int>(std::max(1u, std::thread::hardware_concurrency()));
    fit_materials_in_order(loaders, setup.batch(), request, jobs, [&](std::size_t, MaterialFit&& fit) {
        rows.push_back(recommend(fit, costs, tolerance, target));
    });
    if (o.format == "csv")
        emit(recommendation_table_csv(rows), o.output);
    else if (o.format == "json")
        emit(recommendation_table_json(rows).dump(2) + "\n", o.output);
    else
        emit(recommendation_table_markdown(rows), o.output);
}

}  // namespace

std::function<void()> add_table_command(CLI::App& app, const GlobalOptions& global) {
    auto o = std::make_shared<TableOptions>();
    o->selection.add_options(app, false);
    o->layers.add_options(app);
    add_colour_options(app, o->colour);
    app.add_option("--format", o->format,
                   "csv, json, md (Markdown; default md), physicallybased (physicallybased.info's "
                   "material JSON, srgb-linear and ACEScg whatever --space says) or html (the oxide chart's swatches)")
        ->check(CLI::IsMember({"csv", "json", "md", "physicallybased", "html"}));
    app.add_option("--thickness", o->thickness,
                   "The oxide colour chart of one metal under --film MATERIAL: a row per film thickness, "
                   "FIRST:LAST:STEP with a unit (0:300:10nm; 0 to 2 µm) or one thickness (80nm)");
    app.add_option("--versus", o->versus,
                   "With --thickness: beside each row a film of this constant index (2.488, physicallybased.info's "
                   "anodized titanium) and the CIEDE2000 between the two");
    app.add_flag("--renderers", o->renderers,
                 "With --thickness: score MaterialX's, Belcour & Barla's and a three-wavelength thin film against "
                 "the stack (md, csv, json)");
    app.add_option("-o,--output", o->output, "Write to this file instead of stdout");
    add_recommend_options(app, o->recommend);
    app.add_option("--costs", o->costs,
                   "Cost table of --recommend: a `metalfit bench --json` report (default: built-in llvmpipe ratios)");
    return [o, &global] {
        const Catalog catalog = Catalog::load(global.data_dir);
        const ColourSetup setup = resolve_colour_options(o->colour, global);
        if (o->renderers) {
            if (o->thickness.empty()) throw UsageError("--renderers scores a film: give --film and --thickness");
            run_renderer_scores(*o, global, catalog, setup);
            return;
        }
        if (!o->thickness.empty()) {
            run_chart(*o, global, catalog, setup);
            return;
        }
        if (!o->versus.empty()) throw UsageError("--versus compares the oxide chart's film: give --thickness");
        if (o->format == "html") throw UsageError("--format html is the oxide chart's (--thickness)");
        const bool every_metal = o->selection.materials().empty();
        if (o->recommend.recommend) {
            if (o->format != "md" && o->format != "csv" && o->format != "json")
                throw UsageError("--recommend: the table's formats are md, csv and json");
            run_recommendations(*o, global, catalog, setup, every_metal);
            return;
        }
        if (!o->costs.empty()) throw UsageError("--costs needs --recommend");
        if (o->format == "physicallybased") {
            if (!every_metal || !o->layers.film.empty() || !o->layers.coat.empty())
                throw UsageError(
                    "table --format physicallybased writes the catalog's bare metals: no materials, --film or --coat");
            const ColorSpaceConverter srgb_linear =
                ColorSpaceConverter::create(setup.config, kPhysicallyBasedSrgbLinear, o->colour.xyz_space);
            const ColorSpaceConverter acescg =
                ColorSpaceConverter::create(setup.config, kPhysicallyBasedAcescg, o->colour.xyz_space);
            const PhysicallyBasedTable table =
                physicallybased_table(catalog, {setup.colorimetry, srgb_linear, acescg, setup.spectral});
            emit(physicallybased_json(table).dump(2) + "\n", o->output);
            return;
        }
        const ColorSpaceConverter scene_linear = ColorSpaceConverter::create(setup.config);
        const DisplayTransform display = DisplayTransform::create(setup.config);
        // No material named: every catalog metal (under the layers, when given).
        const auto selected = every_metal ? material_loaders(catalog, true, {}, "", o->selection.labels)
                                          : o->selection.loaders(catalog, "table");
        const auto loaders = o->layers.over(selected, global.data_dir, setup.spectral);
        const MetalTable table =
            metal_table(loaders, catalog, {setup.colorimetry, setup.converter, scene_linear, display, setup.spectral});
        if (o->format == "csv")
            emit(metal_table_csv(table), o->output);
        else if (o->format == "json")
            emit(metal_table_json(table).dump(2) + "\n", o->output);
        else
            emit(metal_table_markdown(table), o->output);
    };
}

}  // namespace metalfit::cli
