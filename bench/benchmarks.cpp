// Google Benchmark suite of metalfit (issue 6), over the kernels of the bench library that `metalfit bench` times:
//   BM_Eval/<kernel>/scalar|array   one RGB evaluation (3 channels) per item: every model, the exact complex
//                                   Fresnel with RGB n,k, the spectral reference, the 64- and 256-entry LUTs
//   BM_Fit/<material>/<model>       fit_model(): closed forms, every Ceres start, metrics (128 nodes)
//   BM_Integration/<N>              the exact spectral reference at N Gauss–Legendre nodes; counters: the relative
//                                   change of each model's fitted rel_rms on the material against 2048 nodes
// Usage: metalfit_benchmarks [--material Au] [Google Benchmark flags, e.g. --benchmark_filter=Eval
//        --benchmark_min_time=0.05]. Data: $METALFIT_DATA or the source tree's data/; OCIO: $OCIO or data/ocio.
#include <benchmark/benchmark.h>

#include <cmath>
#include <cstring>
#include <iostream>
#include <map>
#include <memory>

#include "libfit/data_dir.hpp"
#include "libfit/fit.hpp"
#include "libfit/quadrature.hpp"
#include "metalfit_bench/convergence.hpp"
#include "metalfit_bench/environment.hpp"
#include "metalfit_bench/eval_kernels.hpp"

namespace {

using namespace metalfit;
using namespace metalfit::bench;

void eval(benchmark::State& state, const EvalKernel* kernel, bool array) {
    const std::vector<float> mu = bench_mu(kernel->batch);
    std::vector<float> out(3 * kernel->batch);
    const auto& run = array ? kernel->array : kernel->scalar;
    for (auto _ : state) {
        run(mu, out);
        benchmark::DoNotOptimize(out.data());
        benchmark::ClobberMemory();
    }
    state.SetItemsProcessed(state.iterations() * static_cast<std::int64_t>(kernel->batch));
}

// The per-material inputs of a fit, made once per material (not timed).
struct FitInput {
    Material material;
    ReferenceCurve curve;
    SampledReference reference;
    ClosedFormInput input;
};

const FitInput& fit_input(const Environment& env, const std::string& id) {
    static std::map<std::string, std::unique_ptr<FitInput>> cache;
    auto& slot = cache[id];
    if (!slot) {
        Material material = load_material(env.catalog, id);
        ReferenceCurve curve(material, env.colorimetry, env.converter, env.spectral);
        SampledReference reference(curve, env.error);
        ClosedFormInput input = closed_form_input(curve, material, env.spectral);
        slot = std::make_unique<FitInput>(FitInput{std::move(material), std::move(curve), std::move(reference), std::move(input)});
    }
    return *slot;
}

void fit(benchmark::State& state, const Environment* env, std::string material, const Model* model) {
    const FitInput& in = fit_input(*env, material);
    for (auto _ : state) {
        ModelResult r = fit_model(*model, in.reference, in.input);
        benchmark::DoNotOptimize(r.fit.value.params);
    }
}

void integration(benchmark::State& state, const PreparedMaterial* material, std::map<std::string, double> change) {
    const std::vector<QuadratureNode> nodes = gauss_legendre_unit(static_cast<int>(state.range(0)));
    for (auto _ : state) {
        RGB sum;
        for (const QuadratureNode& q : nodes) {
            const RGB v = material->curve(q.mu);
            sum = {sum.r + q.weight * v.r, sum.g + q.weight * v.g, sum.b + q.weight * v.b};
        }
        benchmark::DoNotOptimize(sum);
    }
    state.SetItemsProcessed(state.iterations() * state.range(0));
    for (const auto& [model, value] : change) state.counters["d_" + model] = value;
}

// Relative change of each model's worst-channel rel_rms at each N against 2048 nodes.
std::map<int, std::map<std::string, double>> convergence(const PreparedMaterial& material) {
    std::map<int, std::map<std::string, double>> out;
    const std::vector<int> counts = convergence_node_counts();
    std::map<double, RGB> cache;
    for (const Model* model : all_models()) {
        const RgbParameters& p = material.params(model->id());
        std::array<Convergence, 3> channel;
        for (int c = 0; c < 3; ++c)
            channel[c] = gauss_legendre_convergence(
                [&](double mu) {
                    auto it = cache.find(mu);
                    if (it == cache.end()) it = cache.emplace(mu, material.curve(mu)).first;
                    const double e = (model->evaluate(std::span<const double>(p[c]), mu) - it->second[c]) / it->second[c];
                    return e * e;
                },
                counts, 2048);
        double at_reference = 0;
        for (int c = 0; c < 3; ++c) at_reference = std::max(at_reference, std::sqrt(channel[c].reference_estimate));
        for (std::size_t i = 0; i < counts.size(); ++i) {
            double at_n = 0;
            for (int c = 0; c < 3; ++c) at_n = std::max(at_n, std::sqrt(channel[c].points[i].estimate));
            out[counts[i]][std::string(model->id())] = std::abs(at_n - at_reference) / at_reference;
        }
    }
    return out;
}

}  // namespace

int main(int argc, char** argv) {
    std::string material_id = "Au";
    std::vector<char*> args;
    for (int i = 0; i < argc; ++i) {
        if (std::strcmp(argv[i], "--material") == 0 && i + 1 < argc) material_id = argv[++i];
        else args.push_back(argv[i]);
    }
    int count = static_cast<int>(args.size());
    benchmark::Initialize(&count, args.data());
    if (benchmark::ReportUnrecognizedArguments(count, args.data())) return 2;
    try {
        static const Environment env = Environment::load(default_data_dir(), std::nullopt);
        static const PreparedMaterial material = PreparedMaterial::prepare(env, material_id);
        static const std::vector<EvalKernel> kernels = eval_kernels(material);
        for (const EvalKernel& k : kernels) {
            benchmark::RegisterBenchmark(("BM_Eval/" + k.id + "/scalar").c_str(), eval, &k, false);
            benchmark::RegisterBenchmark(("BM_Eval/" + k.id + "/array").c_str(), eval, &k, true);
        }
        for (const CatalogEntry& e : env.catalog.entries())
            for (const Model* m : all_models())
                benchmark::RegisterBenchmark(("BM_Fit/" + e.id + "/" + std::string(m->id())).c_str(), fit, &env, e.id, m)
                    ->Unit(benchmark::kMillisecond);
        for (const auto& [nodes, change] : convergence(material))
            benchmark::RegisterBenchmark("BM_Integration", integration, &material, change)
                ->Arg(nodes)
                ->Unit(benchmark::kMicrosecond);
        benchmark::RunSpecifiedBenchmarks();
        benchmark::Shutdown();
    } catch (const std::exception& e) {
        std::cerr << "metalfit_benchmarks: " << e.what() << "\n";
        return 1;
    }
    return 0;
}
