// metalfit fit: closed forms and Ceres fits of cheap Fresnel models for one material or the whole catalog.

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <functional>
#include <iostream>
#include <optional>
#include <sstream>
#include <thread>

#include "colour_options.hpp"
#include "commands.hpp"
#include "error_options.hpp"
#include "layer_options.hpp"
#include "libfit/base/atomic_file.hpp"
#include "libfit/base/errors.hpp"
#include "libfit/base/number_text.hpp"
#include "libfit/export/recommendation.hpp"
#include "libfit/fit/budget.hpp"
#include "libfit/fit/catalog_summary.hpp"
#include "libfit/fit/fit.hpp"
#include "libfit/fit/fit_batch.hpp"
#include "libfit/fit/fit_record.hpp"
#include "libfit/fit/fit_record_stream.hpp"
#include "libfit/fit/model_cost.hpp"
#include "libfit/io/catalog.hpp"
#include "libfit/io/layer_stack.hpp"
#include "material_selection.hpp"
#include "progress.hpp"
#include "recommend_options.hpp"

namespace metalfit::cli {
namespace {

struct FitOptions {
    MaterialSelection selection;
    LayerOptions layers;
    std::string models = "all";
    ColourOptions colour;
    ErrorOptions error;
    int jobs = 0;  // 0: all cores
    bool json = false;
    bool timings = false;
    std::filesystem::path output;
    std::filesystem::path summary;  // --summary: the catalog summary (Markdown)
    std::string pin;                // --pin F0
    bool gamut_fit = false;         // --gamut-fit
    std::string f0_tolerance;       // --f0-tolerance 0.5%
    std::string budget;             // --budget 0.5%
    std::string budget_metric = "rel_rms";
    std::filesystem::path costs;  // --costs BENCH.json
    RecommendOptions recommend;   // --recommend, --target, --max-*
};

std::string params_text(const Model& model, const ModelParameters& p) {
    std::string text;
    const auto parameters = model.parameters();
    for (std::size_t i = 0; i < parameters.size(); ++i) {
        const RGB v = p.parameter(i);
        text += (i ? "  " : "") + std::string(parameters[i].name) + "=(" + fixed(v.r, 4) + ", " + fixed(v.g, 4) + ", " +
                fixed(v.b, 4) + ")";
    }
    return text;
}

std::string pad(std::string s, std::size_t width) {
    // Pads by code points so that "ΔE" and "α" line up.
    std::size_t length = 0;
    for (unsigned char ch : s) length += (ch & 0xC0) != 0x80;
    if (length < width) s.append(width - length, ' ');
    return s;
}

// One table per material: for every model, the best closed form and the fit, relative and absolute RMS per channel
// (in %), worst ΔE2000 and the parameters.
std::string human_table(const MaterialFit& fit, const FitRecordContext& context) {
    const ErrorSettings& e = context.error;
    std::size_t width = 14;  // the model column: 14, or wider for a longer model id
    for (const ModelResult& r : fit.models) width = std::max(width, r.model->id().size() + 1);
    std::ostringstream s;
    s << fit.material.name << " (" << fit.material.id << ", " << fit.material.source << ") in " << context.space << ", "
      << to_string(context.observer) << ", " << to_string(context.illuminant) << ", adaptation "
      << describe_adaptation(context.adaptation, context.adapted, context.illuminant) << ", convention "
      << to_string(context.convention) << "; " << to_string(e.metric) << " metric, " << to_string(e.weight)
      << " weight, " << e.nodes << " nodes\n";
    if (!fit.material.provenance.note.empty()) s << "  caveat: " << fit.material.provenance.note << "\n";
    if (fit.material.layers) s << "  stack: " << describe_stack(fit.material) << "\n";
    s << "  F0 = (" << fixed(fit.F0.r, 5) << ", " << fixed(fit.F0.g, 5) << ", " << fixed(fit.F0.b, 5) << ")";
    if (fit.F0.max() > 1.0 || fit.F0.min() < 0.0) s << "  out of gamut, kept";
    s << "\n";
    if (context.constraints.pin_f0) s << "  F0 pinned: F(1) = R(1) in every channel (--pin F0)\n";
    if (context.constraints.gamut_fit) s << "  fitted curves held in [0, 1] at every angle (--gamut-fit)\n";
    if (context.constraints.f0_tolerance)
        s << "  F0 error held within " << significant_text(100 * *context.constraints.f0_tolerance, 4)
          << " % in every channel (--f0-tolerance)\n";
    s << "  " << pad("model", width) << pad("", 24) << pad("rel_rms % R/G/B", 23) << pad("abs_rms % R/G/B", 23)
      << pad("ΔE00 max", 10) << "parameters\n";
    const auto row = [&](const std::string& model, const std::string& which, const EvaluatedParameters& v,
                         const Model& m, const std::string& note) {
        s << "  " << pad(model, width) << pad(which, 24);
        std::string rel, abs;
        for (int c = 0; c < 3; ++c) {
            rel += (c ? " " : "") + fixed(100 * v.metrics.rel_rms[c], 2);
            abs += (c ? " " : "") + fixed(100 * v.metrics.abs_rms[c], 2);
        }
        s << pad(rel, 23) << pad(abs, 23) << pad(fixed(v.metrics.de2000_max, 2), 10) << params_text(m, v.params) << note
          << "\n";
    };
    for (const ModelResult& r : fit.models) {
        const Model& m = *r.model;
        if (r.best_closed) {
            const ClosedFormResult& best = r.closed_forms[*r.best_closed];
            row(std::string(m.id()), "closed " + best.id, *best.value, m, "");
        }
        for (const ClosedFormResult& form : r.closed_forms)
            if (!form.value)
                s << "  " << pad(r.best_closed ? "" : std::string(m.id()), width) << "closed " << form.id
                  << " undefined: " << form.undefined << "\n";
        std::string note;
        for (int c = 0; c < 3; ++c)
            if (!r.fit.fallback[c].empty())
                note += std::string(note.empty() ? "  (" : ", ") + "RGB"[c] + " kept closed " + r.fit.fallback[c];
        for (int c = 0; c < 3; ++c)
            if (!r.fit.unrepresentable[c].empty())
                note +=
                    std::string(note.empty() ? "  (" : ", ") + "RGB"[c] + " cannot be represented within the bounds";
        for (int c = 0; c < 3; ++c)
            if (const std::string b = at_bound(m, r.fit.value.params[c]); !b.empty())
                note += std::string(note.empty() ? "  (" : ", ") + "RGB"[c] + " on a bound: " + b;
        if (!note.empty()) note += ")";
        row(r.best_closed ? "" : std::string(m.id()), "fit", r.fit.value, m, note);
    }
    return s.str();
}

// The split of the work between phases on stderr: CPU seconds from each fitting thread's own CPU clock, summed over
// materials (their share of the work), and the wall seconds the phases took on their threads; then the run's wall
// time and the process's CPU time (every thread, catalog loading and output included).
void print_timings(const FitTimings& sum, std::size_t materials, double wall_seconds, double process_cpu, int jobs) {
    const PhaseTime total = sum.total();
    // "  <phase, 44 wide> <thread CPU> s  <share> %  <wall> s", the numbers right-aligned under their headings.
    const auto line = [&](const char* phase, const PhaseTime& t) {
        return "  " + pad_right(phase, 44) + " " + pad_left(fixed_text(t.cpu, 3), 8) + " s  " +
               pad_left(fixed_text(total.cpu > 0 ? 100 * t.cpu / total.cpu : 0.0, 1), 5) + " %  " +
               pad_left(fixed_text(t.wall, 3), 8) + " s\n";
    };
    std::string text = "metalfit fit timings: " + std::to_string(materials) + " materials, " + std::to_string(jobs) +
                       " threads, wall " + fixed_text(wall_seconds, 3) + " s, process CPU " +
                       fixed_text(process_cpu, 3) + " s\n";
    text += "  " + pad_right("phase", 44) + " " + pad_left("thread CPU", 10) + "  " + pad_left("share", 7) + "  " +
            pad_left("wall", 10) + "\n";
    text += line("reference curves (spectral integration + OCIO)", sum.reference);
    text += line("closed forms", sum.closed_forms);
    text += line("Ceres fits (all starts)", sum.ceres);
    text += line("metrics (closed forms and fits)", sum.metrics);
    text += line("total over the fitting threads", total);
    std::fputs(text.c_str(), stderr);
}

void run_fit(const FitOptions& o, const GlobalOptions& global) {
    const Catalog catalog = Catalog::load(global.data_dir);
    const auto selected = o.selection.loaders(catalog, "fit");

    const ColourSetup setup = resolve_colour_options(o.colour, global);
    const auto loaders = o.layers.over(selected, global.data_dir, setup.spectral);
    const ErrorSettings error = o.error.settings();
    FitConstraints constraints;
    if (!o.pin.empty()) {
        if (o.pin != "F0") throw UsageError("--pin: only F0 can be pinned (--pin F0)");
        constraints.pin_f0 = true;
    }
    constraints.gamut_fit = o.gamut_fit;
    if (!o.f0_tolerance.empty()) constraints.f0_tolerance = parse_fraction_limit("--f0-tolerance", o.f0_tolerance);
    constraints.check_combination();
    std::optional<Budget> budget;
    if (!o.budget.empty())
        budget = parse_budget(o.budget, parse_budget_metric(o.budget_metric));
    else if (!o.costs.empty() && !o.recommend.recommend)
        throw UsageError("--costs needs --budget or --recommend");
    const std::optional<Tolerance> tolerance = o.recommend.tolerance();
    const ExportFormat target = o.recommend.target_format();
    o.recommend.constrain(constraints);
    const CostTable costs =
        o.costs.empty() ? builtin_cost_table() : cost_table_from_bench_json(o.costs, global.data_dir);
    const MaterialFitRequest request{setup.spectral, error, parse_model_list(o.models), constraints};
    const int jobs = o.jobs > 0 ? o.jobs : static_cast<int>(std::max(1u, std::thread::hardware_concurrency()));
    FitRecordContext context = setup.record_context(error);
    context.constraints = constraints;

    // Streamed: each material's fit is written (record or tables) and let go as it comes, in input order; the
    // output still appears as one unit when the run succeeded (docs/decisions.md, "Streamed fit output").
    std::optional<StreamedOutputFile> out;
    if (o.output.empty() || o.output == "-")
        out.emplace(StreamedOutputFile::StandardOutput{});
    else
        out.emplace(o.output);
    const auto write = [&out](std::string_view text) { out->write(text); };
    std::optional<FitRecordStream> record;
    if (o.json) record.emplace(context, write);
    CatalogSummaryBuilder summary;
    FitTimings timings;
    std::vector<std::string> warnings;  // printed after the run, as before streaming
    std::size_t materials = 0;
    const auto sink = [&](std::size_t index, MaterialFit&& fit) {
        ++materials;
        if (o.timings) timings += fit.timings;
        for (const std::string& w : fit.material.warnings) warnings.push_back(fit.material.id + ": " + w);
        for (std::string& w : refusal_warnings(fit)) warnings.push_back(std::move(w));
        if (!o.summary.empty()) summary.add(fit);
        std::optional<BudgetChoice> choice;
        if (budget) choice = choose_model(fit.models, costs, *budget);
        std::optional<Recommendation> recommendation;
        if (tolerance) recommendation = recommend(fit, costs, *tolerance, target);
        if (record) {
            std::optional<nlohmann::ordered_json> recommended;
            if (recommendation) recommended = recommendation_record(*recommendation);
            record->add(fit, choice ? &*choice : nullptr, recommended ? &*recommended : nullptr);
            return;
        }
        std::string text = (index == 0 ? "" : "\n") + human_table(fit, context);
        if (choice)
            text += "  budget " + budget_text(*budget) + " in every channel: " + choice->summary() +
                    "\n  cost table: " + choice->cost_source + "\n";
        if (recommendation) text += recommendation->text();
        out->write(text);
    };

    const auto start = std::chrono::steady_clock::now();
    const double cpu_start = process_cpu_seconds();
    {
        TerminalProgress progress;
        fit_materials_in_order(loaders, setup.batch(), request, jobs, sink, progress.callback());
    }
    if (o.timings)
        print_timings(timings, materials,
                      std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count(),
                      process_cpu_seconds() - cpu_start, jobs);
    for (const std::string& w : warnings) warn(w);

    if (!o.summary.empty()) emit(catalog_summary_markdown(summary.summary(), context), o.summary);
    if (record) {
        record->finish();
        out->write("\n");
    }
    out->commit();
}

}  // namespace

std::function<void()> add_fit_command(CLI::App& app, const GlobalOptions& global) {
    auto o = std::make_shared<FitOptions>();
    o->selection.add_options(app, true);
    o->layers.add_options(app);
    app.add_option("--model", o->models, "Models, comma-separated, or all: " + model_ids());
    add_colour_options(app, o->colour);
    add_error_options(app, o->error);
    app.add_option("-j,--jobs", o->jobs, "Threads for --all (default: all cores)")->check(CLI::NonNegativeNumber);
    app.add_flag("--json", o->json, "Print the fit record (JSON, docs/fit-record.md)");
    app.add_flag("--timings", o->timings,
                 "Print where the time goes (reference curves, closed forms, Ceres, metrics) on stderr");
    app.add_option("-o,--output", o->output, "Write to this file instead of stdout (- for stdout)");
    app.add_option(
        "--summary", o->summary,
        "Also write the catalog summary (Markdown: worst-channel rel_rms per material and model, median, worst) to this file");
    app.add_option(
        "--pin", o->pin,
        "Hold a value exactly: F0 (F(1) = R(1) in every channel, as physicallybased.info and Adobe tabulate)");
    app.add_flag(
        "--gamut-fit", o->gamut_fit,
        "Fit every channel's curve inside [0, 1] at every angle (constrained, not clipped after; not with --pin F0)");
    app.add_option("--f0-tolerance", o->f0_tolerance,
                   "Fit under |F0 error| <= T in every channel (0.5% or 0.005; a constraint of the solve; not with "
                   "--pin F0 or --gamut-fit)");
    app.add_option(
        "--budget", o->budget,
        "Per material, the cheapest model whose fit meets this error in every channel (0.5% or 0.005; a Delta E for de2000_max)");
    app.add_option("--budget-metric", o->budget_metric,
                   "Metric of --budget: rel_rms, max_rel, f0_err or de2000_max (default: rel_rms)");
    app.add_option("--costs", o->costs,
                   "Cost table for --budget and --recommend: a `metalfit bench --json` report (default: built-in "
                   "llvmpipe ratios, data/model-costs.json)");
    add_recommend_options(app, o->recommend);
    return [o, &global] { run_fit(*o, global); };
}

}  // namespace metalfit::cli
