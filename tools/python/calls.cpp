#include "calls.hpp"

#include <algorithm>
#include <cmath>
#include <thread>

#include "export_options.hpp"
#include "libfit/base/errors.hpp"
#include "libfit/export/export.hpp"
#include "libfit/fit/budget.hpp"
#include "libfit/fit/fit.hpp"
#include "libfit/fit/fit_batch.hpp"
#include "libfit/fit/fit_record_stream.hpp"
#include "libfit/fit/model_cost.hpp"
#include "libfit/io/catalog.hpp"
#include "libfit/reference/reference_curve.hpp"
#include "list_record.hpp"

namespace metalfit::python {
namespace {

int threads(int jobs) { return jobs > 0 ? jobs : static_cast<int>(std::max(1u, std::thread::hardware_concurrency())); }

}  // namespace

std::string catalog_json(const cli::GlobalOptions& global) {
    return cli::list_record(Catalog::load(global.data_dir)).dump(2);
}

std::vector<RGB> reference(const ReferenceOptions& o, const cli::GlobalOptions& global, std::span<const double> mu) {
    // As run_show (tools/metalfit/cmd_show.cpp) for one material.
    const Catalog catalog = Catalog::load(global.data_dir);
    const auto selected = o.selection.loaders(catalog, "show");
    if (selected.size() != 1) throw UsageError("reference: give one material (a catalog name or a file)");
    for (const double m : mu)
        if (!(m >= 0.0 && m <= 1.0))
            throw UsageError("reference: mu must be in [0, 1] (cos θ), got " + std::to_string(m));
    const cli::ColourSetup setup = cli::resolve_colour_options(o.colour, global);
    const auto loaders = o.layers.over(selected, global.data_dir, setup.spectral);
    const Material material = loaders.front()();
    for (const auto& w : material.warnings) cli::warn(w);
    const ReferenceCurve curve(material, setup.colorimetry, setup.converter, setup.spectral);
    for (const auto& w : curve.held_constant()) cli::warn(w);
    return curve(mu);
}

std::string fit_json(const FitOptions& o, const cli::GlobalOptions& global) {
    // As run_fit (tools/metalfit/cmd_fit.cpp) with --json: the same checks in the same order, the same batch fit, the
    // same streamed record.
    const Catalog catalog = Catalog::load(global.data_dir);
    const auto selected = o.selection.loaders(catalog, "fit");
    const cli::ColourSetup setup = cli::resolve_colour_options(o.colour, global);
    const auto loaders = o.layers.over(selected, global.data_dir, setup.spectral);
    const ErrorSettings error = o.error.settings();
    FitConstraints constraints;
    if (!o.pin.empty()) {
        if (o.pin != "F0") throw UsageError("--pin: only F0 can be pinned (--pin F0)");
        constraints.pin_f0 = true;
    }
    constraints.gamut_fit = o.gamut_fit;
    constraints.check_combination();
    std::optional<Budget> budget;
    if (!o.budget.empty())
        budget = parse_budget(o.budget, parse_budget_metric(o.budget_metric));
    else if (!o.costs.empty())
        throw UsageError("--costs needs --budget");
    const CostTable costs =
        o.costs.empty() ? builtin_cost_table() : cost_table_from_bench_json(o.costs, global.data_dir);
    const MaterialFitRequest request{setup.spectral, error, parse_model_list(o.models), constraints};
    FitRecordContext context = setup.record_context(error);
    context.constraints = constraints;

    std::string text;
    FitRecordStream record(context, [&text](std::string_view piece) { text += piece; });
    std::vector<std::string> warnings;
    const auto sink = [&](std::size_t, MaterialFit&& fit) {
        for (const std::string& w : fit.material.warnings) warnings.push_back(fit.material.id + ": " + w);
        std::optional<BudgetChoice> choice;
        if (budget) choice = choose_model(fit.models, costs, *budget);
        record.add(fit, choice ? &*choice : nullptr);
    };
    fit_materials_in_order(loaders, setup.batch(), request, threads(o.jobs), sink);
    for (const std::string& w : warnings) cli::warn(w);
    record.finish();
    return text;
}

std::vector<std::string> export_folder(const ExportOptions& o, const cli::GlobalOptions& global) {
    // As run_export (tools/metalfit/cmd_export.cpp) without best:BUDGET: every argument checked before any work.
    if (o.models.rfind("best:", 0) == 0)
        throw UsageError("export: --model best:BUDGET is not offered by the Python module: fit(..., budget=...) "
                         "names the model to export");
    ExportRequest request{cli::parse_export_formats(o.formats),
                          parse_model_list(o.models),
                          parse_parameter_source(o.params),
                          parse_gamut_policy(o.gamut),
                          o.roughness.empty() ? kDefaultRoughness : cli::parse_roughness(o.roughness),
                          cli::parse_id_prefix(o.id_prefix.empty() ? kDefaultIdPrefix : o.id_prefix)};
    const Catalog catalog = Catalog::load(global.data_dir);
    const auto selected = o.selection.loaders(catalog, "export");
    const cli::ColourSetup setup = cli::resolve_colour_options(o.colour, global);
    const auto loaders = o.layers.over(selected, global.data_dir, setup.spectral);
    const ErrorSettings error{};  // the defaults of `metalfit fit`, as `metalfit export`
    FitConstraints constraints;
    constraints.gamut_fit = o.gamut_fit;
    const MaterialFitRequest fit_request{setup.spectral, error, models_to_fit(request), constraints};
    FitRecordContext context = setup.record_context(error);
    context.constraints = constraints;
    const std::string materialx_space = materialx_colorspace(context.config, context.space);
    if (o.formats == "all")
        if (const std::string left_out =
                leave_out_formats_the_space_cannot_carry(request, context.space, materialx_space);
            !left_out.empty())
            cli::warn(left_out);
    require_export_space(request, context.space, materialx_space);
    const std::vector<MaterialFit> fits = fit_materials(loaders, setup.batch(), fit_request, threads(o.jobs));
    for (const MaterialFit& f : fits)
        for (const auto& w : f.material.warnings) cli::warn(f.material.id + ": " + w);
    for (const std::string& w : export_warnings(context, request, materialx_space)) cli::warn(w);
    const std::vector<ExportFile> files = export_files(fits, context, request, materialx_space);
    write_export(o.output, files);
    std::vector<std::string> written;
    for (const ExportFile& f : files) written.push_back(f.path.generic_string());
    std::sort(written.begin(), written.end());
    return written;
}

}  // namespace metalfit::python
