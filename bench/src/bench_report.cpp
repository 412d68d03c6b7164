#include "metalfit_bench/bench_report.hpp"

#include <chrono>
#include <cmath>
#include <map>

#include "libfit/models/registry.hpp"
#include "metalfit_bench/convergence.hpp"
#include "metalfit_bench/environment.hpp"
#include "metalfit_bench/eval_kernels.hpp"

namespace metalfit::bench {
namespace {

using Clock = std::chrono::steady_clock;

double since(Clock::time_point start) { return std::chrono::duration<double>(Clock::now() - start).count(); }

// The front among the rows `member` selects, on the scalar CPU ratio and on the shader ratio.
void mark_front(std::vector<CostRow>& rows, const ParetoTolerance& tolerance, bool (*member)(const CostRow&),
                CostRow::Front CostRow::*front) {
    std::vector<ParetoPoint> cpu, gpu;
    std::vector<std::size_t> cpu_index, gpu_index;
    for (std::size_t i = 0; i < rows.size(); ++i) {
        rows[i].*front = {};
        if (!member(rows[i])) continue;
        cpu.push_back({rows[i].ratio_scalar.median, rows[i].median_rel_rms});
        cpu_index.push_back(i);
        if (rows[i].shader_ratio) {
            gpu.push_back({*rows[i].shader_ratio, rows[i].median_rel_rms});
            gpu_index.push_back(i);
        }
    }
    const std::vector<bool> cpu_front = pareto_front(cpu, tolerance), gpu_front = pareto_front(gpu, tolerance);
    for (std::size_t k = 0; k < cpu_index.size(); ++k) (rows[cpu_index[k]].*front).cpu = cpu_front[k];
    for (std::size_t k = 0; k < gpu_index.size(); ++k) (rows[gpu_index[k]].*front).gpu = gpu_front[k];
}

}  // namespace

void mark_pareto_fronts(std::vector<CostRow>& rows, const ParetoTolerance& tolerance) {
    mark_front(
        rows, tolerance, [](const CostRow& r) { return r.kind == "model"; }, &CostRow::front_models);
    mark_front(
        rows, tolerance, [](const CostRow&) { return true; }, &CostRow::front_all);
}

BenchReport run_bench(const BenchOptions& o) {
    const auto start = Clock::now();
    const auto say = [&](const std::string& line) {
        if (o.progress) o.progress(line);
    };
    BenchReport report;
    report.command_line = o.command_line;
    report.machine = Machine::describe();
    report.quick = o.quick;
    report.material = o.material;
    report.timing = o.quick ? TimingOptions{5, 0.004} : TimingOptions{21, 0.02};

    const Environment env = Environment::load(o.data_dir, o.ocio_config);
    say("fitting " + o.material + " for the evaluation benchmarks");
    const PreparedMaterial material = PreparedMaterial::prepare(env, o.material);
    report.material = material.material.id;

    say("timing the evaluations (" + std::to_string(report.timing.rounds) + " interleaved rounds)");
    const std::vector<EvalKernel> kernels = eval_kernels(material);
    std::vector<TimedJob> jobs;
    std::vector<std::vector<float>> mus, outs;
    for (const EvalKernel& k : kernels) {
        mus.push_back(bench_mu(k.batch));
        outs.emplace_back(3 * k.batch);
        outs.emplace_back(3 * k.batch);
    }
    for (std::size_t i = 0; i < kernels.size(); ++i) {
        const EvalKernel& k = kernels[i];
        const std::span<const float> mu = mus[i];
        const std::span<float> out_scalar = outs[2 * i], out_array = outs[2 * i + 1];
        jobs.push_back({[&k, mu, out_scalar] { k.scalar(mu, out_scalar); }, static_cast<double>(k.batch)});
        jobs.push_back({[&k, mu, out_array] { k.array(mu, out_array); }, static_cast<double>(k.batch)});
    }
    const std::vector<JobTiming> timings = time_interleaved(jobs, report.timing);
    std::size_t baseline = 0;
    for (std::size_t i = 0; i < kernels.size(); ++i)
        if (kernels[i].id == kBaselineKernel) baseline = i;

    say("fitting the catalog (" + std::to_string(env.catalog.entries().size()) + " materials, every model)");
    const std::array<int, 2> lut_sizes{64, 256};
    const CatalogAccuracy accuracy = catalog_accuracy(env, lut_sizes);
    report.catalog_materials = accuracy.materials.size();

    for (std::size_t i = 0; i < kernels.size(); ++i) {
        const EvalKernel& k = kernels[i];
        CostRow row;
        row.id = k.id;
        row.kind = k.kind;
        row.description = k.description;
        row.params_per_channel = k.params_per_channel;
        const AccuracySummary* a =
            accuracy.find(k.id == "exact-complex" || k.id == "exact-real" ? std::string(kBaselineKernel) : k.id);
        if (a) {
            row.median_rel_rms = a->median;
            row.worst_rel_rms = a->worst;
            row.accuracy_source = k.kind == "lut" ? "the table against the reference at the 128 nodes"
                                  : k.id == "exact-complex" || k.id == "exact-real"
                                      ? "conductor-rgb's fit (the same function)"
                                      : "the fit of every catalog material";
            if (k.kind == "model") row.fit_ms = 1e3 * a->fit_seconds_median;
        } else {
            row.accuracy_source = "exact by definition";
        }
        row.ns_scalar = timings[2 * i].median_ns;
        row.ns_array = timings[2 * i + 1].median_ns;
        row.ratio_scalar = ratio(timings[2 * i], timings[2 * baseline]);
        row.ratio_array = ratio(timings[2 * i + 1], timings[2 * baseline + 1]);
        report.rows.push_back(std::move(row));
    }

    if (o.glslang) {
        say("compiling the models' GLSL to SPIR-V");
        report.spirv_validator = o.glslang->string();
        report.spirv = spirv_costs(*o.glslang);
        for (CostRow& row : report.rows)
            for (const SpirvRow& s : report.spirv)
                if (s.counts && (s.id == row.id || (s.id == "reference-lut" && row.kind == "lut")))
                    row.spirv_ops = s.counts->compute();
    } else {
        report.spirv_skipped = "glslangValidator not found on $PATH (Debian package glslang-tools)";
    }

    say("integrating the reference with 8 … 512 Gauss–Legendre nodes");
    const FittedConvergence convergence = fitted_rel_rms_convergence(material);
    report.convergence_reference_nodes = convergence.reference_nodes;
    report.convergence_models = convergence.models;
    for (std::size_t i = 0; i < convergence.nodes.size(); ++i)
        report.convergence.push_back(
            {convergence.nodes[i], convergence.integration_ms[i], convergence.rel_rms_change[i]});

    say("timing the layers on " + report.material + " (coat, film, both; ratios to the bare metal)");
    report.layers = layers_bench(env, report.material, report.timing);

    say("GPU: " + (o.glpreview.empty() ? std::string("no glpreview") : o.glpreview.string()));
    report.shaders = run_shader_bench(o.glpreview, o.quick);
    report.localization = run_localization_bench(o.glpreview, o.quick);
    if (report.shaders.value)
        for (CostRow& row : report.rows)
            if (const ShaderTiming* t = report.shaders.value->find(row.kind == "lut" ? "reference-lut" : row.id))
                row.shader_ratio = t->ratio_to_conductor_rgb;

    mark_pareto_fronts(report.rows, report.tolerance);
    report.seconds = since(start);
    return report;
}

std::vector<ThesisComparison> thesis_comparison(const BenchReport& report) {
    const std::array<std::pair<const char*, double>, 3> thesis{
        {{models::Schlick::kId.data(), 28}, {models::Lazanyi::kId.data(), 33}, {models::LazanyiComp::kId.data(), 54}}};
    const CostRow* base = nullptr;
    for (const CostRow& r : report.rows)
        if (r.id == kBaselineKernel) base = &r;
    std::vector<ThesisComparison> out;
    for (const auto& [model, percent] : thesis) {
        ThesisComparison c{model, percent, {}, {}, {}, {}};
        for (const CostRow& r : report.rows) {
            if (r.id != model) continue;
            c.cpu_scalar_percent = 100 * r.ratio_scalar.median;
            c.cpu_array_percent = 100 * r.ratio_array.median;
            if (r.spirv_ops && base && base->spirv_ops && *base->spirv_ops > 0)
                c.spirv_percent = 100.0 * *r.spirv_ops / *base->spirv_ops;
            if (r.shader_ratio) c.shader_percent = 100 * *r.shader_ratio;
        }
        out.push_back(c);
    }
    return out;
}

nlohmann::json to_json(const BenchReport& r) {
    using nlohmann::json;
    const auto optional = [](const auto& v) { return v ? json(*v) : json(nullptr); };
    const auto number = [](double v) { return std::isnan(v) ? json(nullptr) : json(v); };
    json rows = json::array();
    for (const CostRow& row : r.rows)
        rows.push_back({{"id", row.id},
                        {"kind", row.kind},
                        {"description", row.description},
                        {"params_per_channel", optional(row.params_per_channel)},
                        {"median_rel_rms", number(row.median_rel_rms)},
                        {"worst_rel_rms", number(row.worst_rel_rms)},
                        {"accuracy_source", row.accuracy_source},
                        {"ns_per_eval_scalar", row.ns_scalar},
                        {"ns_per_eval_array", row.ns_array},
                        {"ratio_scalar", row.ratio_scalar.median},
                        {"ratio_scalar_noise", row.ratio_scalar.noise},
                        {"ratio_array", row.ratio_array.median},
                        {"ratio_array_noise", row.ratio_array.noise},
                        {"fit_ms_per_material", optional(row.fit_ms)},
                        {"spirv_ops", optional(row.spirv_ops)},
                        {"shader_ratio", optional(row.shader_ratio)},
                        {"pareto",
                         {{"models", {{"cpu", row.front_models.cpu}, {"gpu", optional(row.front_models.gpu)}}},
                          {"all", {{"cpu", row.front_all.cpu}, {"gpu", optional(row.front_all.gpu)}}}}}});
    json spirv = json::array();
    for (const SpirvRow& s : r.spirv) {
        json e{{"id", s.id}};
        if (s.counts)
            e.update({{"arithmetic", s.counts->arithmetic},
                      {"transcendental", s.counts->transcendental},
                      {"texture", s.counts->texture},
                      {"other", s.counts->other},
                      {"counted", s.counts->compute()}});
        else
            e["error"] = s.error;
        spirv.push_back(e);
    }
    json convergence = json::array();
    for (const ConvergenceRow& c : r.convergence) {
        json change = json::object();
        for (std::size_t m = 0; m < r.convergence_models.size(); ++m)
            change[r.convergence_models[m]] = number(c.rel_rms_change[m]);
        convergence.push_back({{"nodes", c.nodes}, {"integration_ms", c.integration_ms}, {"rel_rms_change", change}});
    }
    json thesis = json::array();
    for (const ThesisComparison& t : thesis_comparison(r))
        thesis.push_back({{"model", t.model},
                          {"thesis_percent", t.thesis_percent},
                          {"cpu_scalar_percent", optional(t.cpu_scalar_percent)},
                          {"cpu_array_percent", optional(t.cpu_array_percent)},
                          {"spirv_percent", optional(t.spirv_percent)},
                          {"shader_percent", optional(t.shader_percent)}});
    json layers = nullptr;
    if (r.layers) {
        json rows = json::array();
        const auto ratio_json = [](const Ratio& q) { return json{{"median", q.median}, {"noise", q.noise}}; };
        for (const LayersRow& row : r.layers->rows)
            rows.push_back({{"id", row.id},
                            {"stack", row.stack},
                            {"reference_ms", row.reference_ms},
                            {"reference_ratio", ratio_json(row.reference_ratio)},
                            {"fit_ms", row.fit_ms},
                            {"fit_ratio", ratio_json(row.fit_ratio)}});
        layers = {{"material", r.layers->material}, {"model", r.layers->model}, {"rows", rows}};
    }
    const auto gpu = [](const auto& section) {
        return section.value ? json{{"result", to_json(*section.value)}, {"skipped", nullptr}}
                             : json{{"result", nullptr}, {"skipped", section.skipped}};
    };
    return {{"schema", "metalfit.bench/1"},
            {"command", r.command_line},
            {"machine", to_json(r.machine)},
            {"quick", r.quick},
            {"material", r.material},
            {"catalog_materials", r.catalog_materials},
            {"timing",
             {{"rounds", r.timing.rounds},
              {"seconds_per_sample", r.timing.seconds_per_sample},
              {"baseline", kBaselineKernel},
              {"clock", clock_name(r.timing.clock)}}},
            {"pareto_tolerance",
             {{"cost", r.tolerance.cost}, {"error", r.tolerance.error}, {"error_floor", r.tolerance.error_floor}}},
            {"rows", rows},
            {"spirv",
             {{"validator", r.spirv_validator.empty() ? json(nullptr) : json(r.spirv_validator)},
              {"skipped", r.spirv_skipped.empty() ? json(nullptr) : json(r.spirv_skipped)},
              {"shaders", spirv}}},
            {"convergence",
             {{"material", r.material}, {"reference_nodes", r.convergence_reference_nodes}, {"rows", convergence}}},
            {"layers", layers},
            {"gpu", {{"shaders", gpu(r.shaders)}, {"localization", gpu(r.localization)}}},
            {"thesis_table_3_2", thesis},
            {"seconds", r.seconds}};
}

}  // namespace metalfit::bench
