#include "report_tables.hpp"

#include <cmath>
#include <cstdio>

#include "libfit/base/number_text.hpp"
#include "metalfit_bench/eval_kernels.hpp"

namespace metalfit::bench::detail {
namespace {

// The table's numbers; "-" for NaN (not measured).
std::string fixed(double v, int decimals) { return std::isnan(v) ? "-" : fixed_text(v, decimals); }
std::string significant(double v, int digits) { return std::isnan(v) ? "-" : significant_text(v, digits); }
std::string scientific(double v, int decimals) { return std::isnan(v) ? "-" : scientific_text(v, decimals); }

// rel_rms in % with three significant digits (0.0213, 1.09, 10.8).
std::string percent(double v) {
    if (std::isnan(v)) return "-";
    if (v == 0) return "0";
    const double p = 100 * v;
    return p >= 0.1 ? fixed(p, p >= 10 ? 1 : p >= 1 ? 2 : 3) : significant(p, 2);
}

std::string ns(double v) { return fixed(v, v >= 100 ? 0 : v >= 10 ? 1 : 2); }

// Three significant digits (0.0712, 1.00, 7.38, 1038) and the noise with the same number of decimals.
std::string ratio_text(const Ratio& r) {
    const int decimals = r.median >= 100 ? 0 : r.median >= 10 ? 1 : r.median >= 1 ? 2 : r.median >= 0.1 ? 3 : 4;
    return fixed(r.median, decimals) + " ±" + fixed(r.noise, decimals);
}

std::string front_text(const CostRow::Front& f) {
    std::string s;
    if (f.cpu) s = "CPU";
    if (f.gpu && *f.gpu) s += s.empty() ? "GPU" : " GPU";
    return s.empty() ? "" : "* " + s;
}

}  // namespace

std::string run_line(const BenchReport& r) {
    return std::string(r.quick ? "quick run" : "full run") + ": evaluation of " + r.material +
           "'s fitted parameters, " + std::to_string(r.timing.rounds) + " interleaved rounds of " +
           fixed(1e3 * r.timing.seconds_per_sample, 0) + " ms per kernel (" + clock_name(r.timing.clock) +
           " clock); accuracy over " + std::to_string(r.catalog_materials) +
           " catalog materials (worst channel rel_rms, 128 nodes); wall " + fixed(r.seconds, 1) + " s";
}

std::vector<std::string> skipped_lines(const BenchReport& r) {
    std::vector<std::string> lines;
    if (!r.spirv_skipped.empty()) lines.push_back("SPIR-V section skipped: " + r.spirv_skipped);
    const bool shaders = !r.shaders.value, localization = !r.localization.value;
    if (shaders && localization && r.shaders.skipped == r.localization.skipped)
        lines.push_back("GPU sections skipped: " + r.shaders.skipped);
    else {
        if (shaders) lines.push_back("GPU shader section skipped: " + r.shaders.skipped);
        if (localization) lines.push_back("GPU localization section skipped: " + r.localization.skipped);
    }
    return lines;
}

std::vector<Table> report_tables(const BenchReport& r) {
    std::vector<Table> tables;

    Table main{"Accuracy against cost (ratios to " + std::string(kBaselineKernel) + ", measured in this run)",
               {"model", "params/ch", "median rel_rms %", "worst rel_rms %", "ns/eval", "ns/eval array", "ratio",
                "ratio array", "fit ms", "SPIR-V ops", "shader ratio", "front models", "front all"},
               {},
               {}};
    for (const CostRow& row : r.rows)
        main.rows.push_back(
            {row.id, row.params_per_channel ? std::to_string(*row.params_per_channel) : "-",
             percent(row.median_rel_rms), percent(row.worst_rel_rms), ns(row.ns_scalar), ns(row.ns_array),
             ratio_text(row.ratio_scalar), ratio_text(row.ratio_array), row.fit_ms ? fixed(*row.fit_ms, 1) : "-",
             row.spirv_ops ? std::to_string(*row.spirv_ops) : "-", row.shader_ratio ? fixed(*row.shader_ratio, 2) : "-",
             front_text(row.front_models), front_text(row.front_all)});
    main.notes = {
        "ns/eval: one RGB evaluation (3 channels), float, one μ at a time; array: a loop over 1024 μ the compiler may "
        "vectorise. Ratios: median over rounds of the per-round ratio, ± half its interquartile range.",
        "exact-complex: libfit's complex Fresnel in double with conductor-rgb's fitted n,k; exact-real: the same in "
        "libfit's real branch-free form (fresnel_real, float; its array loop vectorises); spectral-reference: 471 "
        "wavelengths × CMF + OCIO per μ; lut-N: N float RGB entries, linear interpolation (accuracy: the table "
        "against the reference).",
        "fit ms: fit_model() per material (closed forms, every Ceres start, metrics), median over the catalog.",
        "Pareto front (*): no other row is both cheaper and more accurate (median rel_rms), among the models only and "
        "among all rows; CPU on the scalar ratio, GPU on the shader ratio; costs within " +
            fixed(100 * r.tolerance.cost, 0) + " % and errors within " + fixed(100 * r.tolerance.error, 0) +
            " % are ties."};
    tables.push_back(std::move(main));

    Table thesis{"Against the thesis's Table 3.2 (time relative to the exact Fresnel, %)",
                 {"model", "thesis", "CPU scalar", "CPU array", "SPIR-V ops", "GPU shader"},
                 {},
                 {}};
    const auto pct = [](const std::optional<double>& v) { return v ? fixed(*v, 0) : std::string("-"); };
    for (const ThesisComparison& t : thesis_comparison(r))
        thesis.rows.push_back({t.model, fixed(t.thesis_percent, 0), pct(t.cpu_scalar_percent), pct(t.cpu_array_percent),
                               pct(t.spirv_percent), pct(t.shader_percent)});
    thesis.notes = {"The exact Fresnel here is conductor-rgb (the thesis's real form, float); SPIR-V ops: counted "
                    "instructions relative to conductor-rgb's."};
    tables.push_back(std::move(thesis));

    if (!r.spirv.empty()) {
        Table spirv{"SPIR-V instructions per category (glslangValidator -V -Os, fragment shader around each function)",
                    {"shader", "arithmetic", "transcendental", "texture", "other", "counted"},
                    {},
                    {}};
        for (const SpirvRow& s : r.spirv) {
            if (s.counts)
                spirv.rows.push_back({s.id, std::to_string(s.counts->arithmetic),
                                      std::to_string(s.counts->transcendental), std::to_string(s.counts->texture),
                                      std::to_string(s.counts->other), std::to_string(s.counts->compute())});
            else
                spirv.rows.push_back({s.id, "error: " + s.error, "", "", "", ""});
        }
        spirv.notes = {"counted = arithmetic + transcendental + texture; \"other\" (loads, stores, composites, "
                       "compares, selects, returns) includes the wrapper's own, shown in the row \"wrapper\"."};
        tables.push_back(std::move(spirv));
    }

    Table convergence{"Gauss–Legendre convergence on " + r.material +
                          " (spectral integration cost; change of each "
                          "fit's worst-channel rel_rms against " +
                          std::to_string(r.convergence_reference_nodes) + " nodes)",
                      {"nodes", "integration ms"},
                      {},
                      {}};
    for (const std::string& m : r.convergence_models) convergence.headers.push_back(m);
    for (const ConvergenceRow& c : r.convergence) {
        std::vector<std::string> row{std::to_string(c.nodes), fixed(c.integration_ms, 2)};
        for (double v : c.rel_rms_change) row.push_back(scientific(v, 1));
        convergence.rows.push_back(std::move(row));
    }
    convergence.notes = {"integration ms: the exact spectral reference at the N nodes (N × 471 wavelengths + OCIO), "
                         "once; the model columns are relative changes (1e-3 = 0.1 % of the rel_rms itself)."};
    tables.push_back(std::move(convergence));

    if (r.layers) {  // issue 28, goal 10: a stack's cost as ratios to the bare metal's, this run
        Table layers{"Layers on " + r.layers->material + ": the stack's reference curve and its " + r.layers->model +
                         " fit, as ratios to the bare metal's (measured in this run)",
                     {"stack", "reference ms", "ratio ± noise", "fit ms", "ratio ± noise"},
                     {},
                     {}};
        for (const LayersRow& row : r.layers->rows)
            layers.rows.push_back({row.stack, fixed(row.reference_ms, 3), ratio_text(row.reference_ratio),
                                   fixed(row.fit_ms, 2), ratio_text(row.fit_ratio)});
        layers.notes = {"reference: the curve built from the spectral data (the layers' optics on the colour grid, "
                        "OCIO) and sampled at the fit's nodes; fit: fit_material with that model (closed forms, "
                        "Ceres, metrics). Coat n = 1.5, film TiO2 (Siefke) 80 nm."};
        tables.push_back(std::move(layers));
    }

    if (r.shaders.value) {
        const ShaderBench& b = *r.shaders.value;
        Table t{"GPU: full-screen model pass at " + std::to_string(b.width) + "x" + std::to_string(b.height) + ", " +
                    std::to_string(b.frames) + " frames (" + b.renderer + ")",
                {"shader", "ms/frame", "ratio to conductor-rgb"},
                {},
                {}};
        for (const ShaderTiming& s : b.models)
            t.rows.push_back({s.model, fixed(s.ms_per_frame, 3), fixed(s.ratio_to_conductor_rgb, 2)});
        t.notes = {"each pixel evaluates the model " + std::to_string(b.evaluations_per_pixel) +
                   " time(s) at different μ, so that the pass measures the model rather than the framebuffer write; "
                   "frames of all shaders interleaved round-robin, median per shader; reference-lut: a 256-texel "
                   "1D texture lookup."};
        tables.push_back(std::move(t));
    }
    if (r.localization.value) {
        const LocalizationBench& b = *r.localization.value;
        Table t{
            "GPU: localization at " + std::to_string(b.width) + "x" + std::to_string(b.height) + " (" + b.renderer +
                "), error against the CPU ray-traced reference",
            {"room", "mode", "strategy", "iterations (limit)", "search steps", "mean steps", "ms/frame",
             "ratio to classic ± noise", "rmse", "mean abs"},
            {},
            {"iterations: the most refinement steps a pixel may take; mean steps: those its pixels took (each stops once "
             "|rho - 1| < the tolerance); search steps: the linear search's distance reads before the refinement (at most; it "
             "stops at the first overshoot); noise: half the interquartile range of the per-round ratios."}};
        bool implausible = false;
        for (const LocalizationRoom& room : b.rooms)
            for (const LocalizationRow& row : room.rows) {
                t.rows.push_back({room.room, row.mode, row.strategy.value_or("-"), std::to_string(row.iterations),
                                  std::to_string(row.search_steps), fixed(row.mean_iterations, 2),
                                  fixed(row.ms_per_frame, 3),
                                  fixed(row.ratio_to_classic, 2) + " ± " + fixed(row.ratio_noise, 2),
                                  significant(row.rmse, 4), significant(row.mean_abs, 4)});
                // A lookup that costs more than classic's cannot be cheaper beyond its noise: the machine's load is.
                if (row.mean_iterations > 0 && row.ratio_to_classic + row.ratio_noise < 1.0) implausible = true;
            }
        if (implausible)
            t.notes.push_back(
                "warning: some impostor rows are cheaper than classic beyond their noise: the timings are "
                "dominated by load on the machine; rerun on an idle one.");
        tables.push_back(std::move(t));
    }
    return tables;
}

}  // namespace metalfit::bench::detail
