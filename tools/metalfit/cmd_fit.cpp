// metalfit fit: closed forms and Ceres fits of cheap Fresnel models for one material or the whole catalog.

#include <algorithm>
#include <chrono>
#include <cstdio>
#include <functional>
#include <iostream>
#include <sstream>
#include <thread>

#include "colour_options.hpp"
#include "commands.hpp"
#include "progress.hpp"
#include "libfit/io/catalog.hpp"
#include "libfit/base/errors.hpp"
#include "libfit/fit/fit.hpp"
#include "libfit/fit/catalog_summary.hpp"
#include "libfit/fit/fit_record.hpp"

namespace metalfit::cli {
namespace {

struct FitOptions {
    std::string material;
    bool all = false;
    std::string source;
    UserFileLabels labels;
    std::string models = "all";
    ColourOptions colour;
    std::string metric = "rel";
    std::string weight = "uniform";
    int nodes = 128;
    int jobs = 0;  // 0: all cores
    bool json = false;
    bool timings = false;
    std::filesystem::path output;
    std::filesystem::path summary;  // --summary: the catalog summary (Markdown)
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
    std::ostringstream s;
    s << fit.material.name << " (" << fit.material.id << ", " << fit.material.source << ") in " << context.space << ", "
      << to_string(context.observer) << ", " << to_string(context.illuminant) << "; " << to_string(e.metric)
      << " metric, " << to_string(e.weight) << " weight, " << e.nodes << " nodes\n";
    if (!fit.material.provenance.note.empty()) s << "  caveat: " << fit.material.provenance.note << "\n";
    s << "  F0 = (" << fixed(fit.F0.r, 5) << ", " << fixed(fit.F0.g, 5) << ", " << fixed(fit.F0.b, 5) << ")";
    if (fit.F0.max() > 1.0 || fit.F0.min() < 0.0) s << "  out of gamut, kept";
    s << "\n";
    s << "  " << pad("model", 14) << pad("", 24) << pad("rel_rms % R/G/B", 23) << pad("abs_rms % R/G/B", 23)
      << pad("ΔE00 max", 10) << "parameters\n";
    const auto row = [&](const std::string& model, const std::string& which, const EvaluatedParameters& v,
                         const Model& m, const std::string& note) {
        s << "  " << pad(model, 14) << pad(which, 24);
        std::string rel, abs;
        for (int c = 0; c < 3; ++c) {
            rel += (c ? " " : "") + fixed(100 * v.metrics.rel_rms[c], 2);
            abs += (c ? " " : "") + fixed(100 * v.metrics.abs_rms[c], 2);
        }
        s << pad(rel, 23) << pad(abs, 23) << pad(fixed(v.metrics.de2000_max, 2), 10) << params_text(m, v.params)
          << note << "\n";
    };
    for (const ModelResult& r : fit.models) {
        const Model& m = *r.model;
        if (r.best_closed) {
            const ClosedFormResult& best = r.closed_forms[*r.best_closed];
            row(std::string(m.id()), "closed " + best.id, *best.value, m, "");
        }
        for (const ClosedFormResult& form : r.closed_forms)
            if (!form.value) s << "  " << pad(r.best_closed ? "" : std::string(m.id()), 14) << "closed " << form.id
                               << " undefined: " << form.undefined << "\n";
        std::string note;
        for (int c = 0; c < 3; ++c)
            if (!r.fit.fallback[c].empty()) note += std::string(note.empty() ? "  (" : ", ") + "RGB"[c] + " kept closed " + r.fit.fallback[c];
        if (!note.empty()) note += ")";
        row(r.best_closed ? "" : std::string(m.id()), "fit", r.fit.value, m, note);
    }
    return s.str();
}

// The split of the work between phases (thread seconds summed over materials) and the wall time, on stderr.
void print_timings(const std::vector<MaterialFit>& fits, double wall_seconds, int jobs) {
    FitTimings sum;
    for (const MaterialFit& f : fits) sum += f.timings;
    const double total = sum.total();
    const auto line = [&](const char* phase, double seconds) {
        std::fprintf(stderr, "  %-44s %8.3f s  %5.1f %%\n", phase, seconds, total > 0 ? 100 * seconds / total : 0.0);
    };
    std::fprintf(stderr, "metalfit fit timings: %zu materials, %d threads, wall %.3f s\n", fits.size(), jobs, wall_seconds);
    line("reference curves (spectral integration + OCIO)", sum.reference);
    line("closed forms", sum.closed_forms);
    line("Ceres fits (all starts)", sum.ceres);
    line("metrics (closed forms and fits)", sum.metrics);
    line("total thread time", total);
}

void run_fit(const FitOptions& o, const GlobalOptions& global) {
    if (!o.all && o.material.empty()) throw UsageError("fit: give a material (catalog name or file), or --all");
    if (o.all && !o.material.empty()) throw UsageError("fit: give a material or --all, not both");
    if (o.all && !o.source.empty()) throw UsageError("fit: --source needs a single material");
    const Catalog catalog = Catalog::load(global.data_dir);
    const auto loaders = material_loaders(catalog, o.all, o.material, o.source, o.labels);

    const ColourSetup setup = resolve_colour_options(o.colour, global);
    const ErrorSettings error{o.nodes, parse_error_metric(o.metric), parse_angular_weight(o.weight)};
    const MaterialFitRequest request{setup.spectral, error, parse_model_list(o.models)};
    const int jobs = o.jobs > 0 ? o.jobs : static_cast<int>(std::max(1u, std::thread::hardware_concurrency()));
    const auto start = std::chrono::steady_clock::now();
    TerminalProgress progress;
    const std::vector<MaterialFit> fits = fit_materials(loaders, setup.batch(), request, jobs, progress.callback());
    if (o.timings) print_timings(fits, std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count(), jobs);
    for (const MaterialFit& f : fits)
        for (const auto& w : f.material.warnings) warn(f.material.id + ": " + w);

    const FitRecordContext context{setup.config, setup.converter.space(), setup.colorimetry.observer(),
                                   setup.colorimetry.illuminant(), setup.spectral, error};
    if (!o.summary.empty()) emit(catalog_summary_markdown(summarize_catalog(fits), context), o.summary);
    if (o.json) {
        emit(fit_record(fits, context).dump(2) + "\n", o.output);
        return;
    }
    std::string text;
    for (const MaterialFit& f : fits) text += (text.empty() ? "" : "\n") + human_table(f, context);
    emit(text, o.output);
}

}  // namespace

std::function<void()> add_fit_command(CLI::App& app, const GlobalOptions& global) {
    auto o = std::make_shared<FitOptions>();
    app.add_option("material", o->material, "Catalog material (id, name or alias) or a .yml/.csv/.tsv/.txt/.dat file");
    app.add_flag("--all", o->all, "Every material of the built-in catalog, in parallel");
    app.add_option("--source", o->source, "Alternate source of a catalog material (default: its primary)");
    app.add_option("--name", o->labels.name, "Name of the material in a file of your own (default: the file stem)");
    app.add_option("--reference", o->labels.reference,
                   "Literature reference of a file of your own, shown and exported (default: the file's REFERENCES)");
    app.add_option("--model", o->models, "Models, comma-separated, or all (default: all)");
    add_colour_options(app, o->colour);
    app.add_option("--metric", o->metric, "Error the fit minimises: rel or abs")->check(CLI::IsMember({"rel", "abs"}));
    app.add_option("--weight", o->weight, "Angular weight: uniform (in mu) or cosine (2 mu)")
        ->check(CLI::IsMember({"uniform", "cosine"}));
    app.add_option("--nodes", o->nodes, "Gauss-Legendre nodes on [0, 1]")->check(CLI::Range(2, 4096));
    app.add_option("-j,--jobs", o->jobs, "Threads for --all (default: all cores)")->check(CLI::NonNegativeNumber);
    app.add_flag("--json", o->json, "Print the fit record (JSON, docs/fit-record.md)");
    app.add_flag("--timings", o->timings, "Print where the time goes (reference curves, closed forms, Ceres, metrics) on stderr");
    app.add_option("-o,--output", o->output, "Write to this file instead of stdout");
    app.add_option("--summary", o->summary,
                   "Also write the catalog summary (Markdown: worst-channel rel_rms per material and model, median, worst) to this file");
    return [o, &global] { run_fit(*o, global); };
}

}  // namespace metalfit::cli
