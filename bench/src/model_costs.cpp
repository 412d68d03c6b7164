#include "metalfit_bench/model_costs.hpp"

#include <cmath>
#include <stdexcept>

#include "libfit/base/interleaved_timer.hpp"
#include "libfit/base/number_text.hpp"
#include "libfit/base/sample_statistics.hpp"
#include "libfit/models/registry.hpp"
#include "metalfit_bench/environment.hpp"
#include "metalfit_bench/eval_kernels.hpp"
#include "metalfit_bench/glpreview_results.hpp"
#include "metalfit_bench/spirv_cost.hpp"

namespace metalfit::bench {
namespace {

using nlohmann::ordered_json;

MeasuredRatio measured(const std::vector<double>& a, const std::vector<double>& b) {
    std::vector<double> per_round;
    for (std::size_t i = 0; i < a.size() && i < b.size(); ++i) per_round.push_back(a[i] / b[i]);
    const Ratio r = paired_ratio(a, b);
    return {r.median, r.noise, {quantile(per_round, 0.25), quantile(per_round, 0.75)}};
}

ordered_json to_json(const MeasuredRatio& r) {
    return {{"ratio", r.ratio}, {"noise", r.noise}, {"quartiles", {r.quartiles[0], r.quartiles[1]}}};
}

}  // namespace

ModelCosts measure_model_costs(const ModelCostsOptions& o) {
    const auto say = [&](const std::string& line) {
        if (o.progress) o.progress(line);
    };
    if (!o.glslang) throw std::runtime_error("glslangValidator not found on $PATH (Debian package glslang-tools)");
    ModelCosts costs;
    costs.command_line = o.command_line;
    costs.machine = Machine::describe();
    costs.cpu_rounds = o.cpu_rounds;
    costs.seconds_per_sample = o.seconds_per_sample;
    costs.validator = "glslangValidator -V -Os";

    say("timing the shaders on the software GPU (glpreview --bench-shaders)");
    const GpuSection<ShaderBench> gpu = run_shader_bench(o.glpreview, false);
    if (!gpu.value) throw std::runtime_error(gpu.skipped);
    costs.renderer = gpu.value->renderer;
    costs.gpu_clock = gpu.value->clock;
    costs.gpu_rounds = gpu.value->frames;
    costs.gpu_size = gpu.value->width;
    costs.evaluations_per_pixel = gpu.value->evaluations_per_pixel;

    const Environment env = Environment::load(o.data_dir, o.ocio_config);
    say("fitting " + o.material + " for the CPU kernels");
    const PreparedMaterial material = PreparedMaterial::prepare(env, o.material);
    costs.material = material.material.id;
    say("timing the models' array loops (" + std::to_string(o.cpu_rounds) + " interleaved rounds, thread CPU time)");
    std::vector<EvalKernel> kernels;
    for (EvalKernel& k : eval_kernels(material))
        if (k.kind == "model") kernels.push_back(std::move(k));
    std::vector<std::vector<float>> mus, outs;
    for (const EvalKernel& k : kernels) {
        mus.push_back(bench_mu(k.batch));
        outs.emplace_back(3 * k.batch);
    }
    std::vector<TimedJob> jobs;
    for (std::size_t i = 0; i < kernels.size(); ++i) {
        const std::span<const float> mu = mus[i];
        const std::span<float> out = outs[i];
        jobs.push_back({[&k = kernels[i], mu, out] { k.array(mu, out); }, static_cast<double>(kernels[i].batch)});
    }
    const std::vector<JobTiming> timings =
        time_interleaved(jobs, {o.cpu_rounds, o.seconds_per_sample, TimingClock::thread_cpu});
    std::size_t baseline = kernels.size();
    for (std::size_t i = 0; i < kernels.size(); ++i)
        if (kernels[i].id == kBaselineKernel) baseline = i;
    if (baseline == kernels.size()) throw std::logic_error("no conductor-rgb kernel");

    say("compiling the models' GLSL to SPIR-V");
    const std::vector<SpirvRow> spirv = spirv_costs(*o.glslang);

    std::vector<double> gpu_ratio, cpu_ratio, ops, weighted;
    for (std::size_t i = 0; i < kernels.size(); ++i) {
        ModelCostRow row;
        row.model = kernels[i].id;
        const ShaderTiming* t = gpu.value->find(row.model);
        if (!t || !t->ratio_noise || !t->ratio_quartiles)
            throw std::runtime_error("glpreview --bench-shaders has no ratio with its noise for " + row.model);
        row.gpu = {t->ratio_to_conductor_rgb, *t->ratio_noise, *t->ratio_quartiles};
        row.cpu_array = measured(timings[i].ns_per_item, timings[baseline].ns_per_item);
        bool counted = false;
        for (const SpirvRow& s : spirv)
            if (s.id == row.model) {
                if (!s.counts) throw std::runtime_error("SPIR-V of " + row.model + ": " + s.error);
                row.spirv_ops = s.counts->compute();
                row.spirv_weighted = s.counts->weighted;
                counted = true;
            }
        if (!counted) throw std::logic_error("no SPIR-V row for " + row.model);
        gpu_ratio.push_back(row.gpu.ratio);
        cpu_ratio.push_back(row.cpu_array.ratio);
        ops.push_back(row.spirv_ops);
        weighted.push_back(row.spirv_weighted);
        costs.rows.push_back(std::move(row));
    }
    costs.weighted_vs_gpu = spearman(weighted, gpu_ratio);
    costs.weighted_vs_cpu = spearman(weighted, cpu_ratio);
    costs.ops_vs_gpu = spearman(ops, gpu_ratio);
    costs.ops_vs_cpu = spearman(ops, cpu_ratio);
    costs.cpu_vs_gpu = spearman(cpu_ratio, gpu_ratio);
    return costs;
}

nlohmann::ordered_json to_json(const ModelCosts& c) {
    ordered_json models = ordered_json::array();
    for (const ModelCostRow& r : c.rows)
        models.push_back({{"model", r.model},
                          {"llvmpipe", to_json(r.gpu)},
                          {"cpu_array", to_json(r.cpu_array)},
                          {"spirv_ops", r.spirv_ops},
                          {"spirv_weighted", r.spirv_weighted}});
    ordered_json j = {{"schema", "metalfit.model-costs/1"},
                      {"command", c.command_line},
                      {"regenerate", "scripts/measure-model-costs.sh"},
                      {"cost", "llvmpipe"},
                      {"baseline", kBaselineKernel},
                      {"machine", ordered_json::parse(to_json(c.machine).dump())},
                      {"llvmpipe",
                       {{"renderer", c.renderer},
                        {"clock", c.gpu_clock},
                        {"rounds", c.gpu_rounds},
                        {"size", c.gpu_size},
                        {"evaluations_per_pixel", c.evaluations_per_pixel}}},
                      {"cpu_array",
                       {{"material", c.material},
                        {"clock", "thread-cpu"},
                        {"rounds", c.cpu_rounds},
                        {"seconds_per_sample", c.seconds_per_sample}}},
                      {"spirv",
                       {{"compiler", c.validator},
                        {"weights",
                         {{"arithmetic_lane", 1},
                          {"division_lane", 5},
                          {"sqrt_exp2_log2_sin_cos_lane", 4},
                          {"exp_log_lane", 5},
                          {"pow_lane", 9},
                          {"other_transcendental_lane", 8},
                          {"texture", 4}}}}},
                      {"models", models},
                      {"spearman",
                       {{"spirv_weighted_vs_llvmpipe", c.weighted_vs_gpu},
                        {"spirv_weighted_vs_cpu_array", c.weighted_vs_cpu},
                        {"spirv_ops_vs_llvmpipe", c.ops_vs_gpu},
                        {"spirv_ops_vs_cpu_array", c.ops_vs_cpu},
                        {"cpu_array_vs_llvmpipe", c.cpu_vs_gpu}}}};
    return j;
}

std::string to_text(const ModelCosts& c) {
    std::string t = "Model costs as ratios to conductor-rgb (" + c.command_line + "; " + c.machine.one_line() +
                    ")\nsoftware GPU: " + c.renderer + ", " + std::to_string(c.gpu_size) + "² × " +
                    std::to_string(c.evaluations_per_pixel) + " evaluations per pixel, " +
                    std::to_string(c.gpu_rounds) + " interleaved rounds, " + c.gpu_clock +
                    " clock; CPU: array of 1024 μ (" + c.material + "), " + std::to_string(c.cpu_rounds) +
                    " interleaved rounds, thread-cpu clock; ± half the interquartile range\n\n";
    t += "| model | llvmpipe | CPU array | SPIR-V ops | SPIR-V weighted |\n|---|---|---|---|---|\n";
    for (const ModelCostRow& r : c.rows)
        t += "| " + r.model + " | " + fixed_text(r.gpu.ratio, 3) + " ± " + fixed_text(r.gpu.noise, 3) + " | " +
             fixed_text(r.cpu_array.ratio, 3) + " ± " + fixed_text(r.cpu_array.noise, 3) + " | " +
             std::to_string(r.spirv_ops) + " | " + fixed_text(r.spirv_weighted, 0) + " |\n";
    t += "\nSpearman rank correlation: SPIR-V weighted vs llvmpipe " + fixed_text(c.weighted_vs_gpu, 2) +
         ", vs CPU array " + fixed_text(c.weighted_vs_cpu, 2) + "; SPIR-V ops vs llvmpipe " +
         fixed_text(c.ops_vs_gpu, 2) + ", vs CPU array " + fixed_text(c.ops_vs_cpu, 2) + "; CPU array vs llvmpipe " +
         fixed_text(c.cpu_vs_gpu, 2) + "\n";
    return t;
}

}  // namespace metalfit::bench
