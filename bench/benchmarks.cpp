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

#include "libfit/base/data_dir.hpp"
#include "libfit/base/quadrature.hpp"
#include "libfit/fit/fit.hpp"
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

// The per-material inputs of a fit, made once per material (not timed). The closed-form input refers to the curve,
// so both live at a fixed address.
struct FitInput {
    FitInput(const Environment& env, const std::string& id)
        : material(load_material(env.catalog, id)),
          curve(material, env.colorimetry, env.converter, env.spectral),
          reference(curve, env.error),
          input(closed_form_input(curve, material, env.spectral)) {}
    Material material;
    ReferenceCurve curve;
    SampledReference reference;
    ClosedFormInput input;
};

const FitInput& fit_input(const Environment& env, const std::string& id) {
    static std::map<std::string, std::unique_ptr<const FitInput>> cache;
    auto& slot = cache[id];
    if (!slot) slot = std::make_unique<const FitInput>(env, id);
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

}  // namespace

int main(int argc, char** argv) {
    std::string material_id = "Au";
    std::vector<char*> args;
    for (int i = 0; i < argc; ++i) {
        if (std::strcmp(argv[i], "--material") == 0 && i + 1 < argc)
            material_id = argv[++i];
        else
            args.push_back(argv[i]);
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
                benchmark::RegisterBenchmark(("BM_Fit/" + e.id + "/" + std::string(m->id())).c_str(), fit, &env, e.id,
                                             m)
                    ->Unit(benchmark::kMillisecond);
        const FittedConvergence convergence = fitted_rel_rms_convergence(material);
        for (std::size_t i = 0; i < convergence.nodes.size(); ++i) {
            std::map<std::string, double> change;
            for (std::size_t m = 0; m < convergence.models.size(); ++m)
                change[convergence.models[m]] = convergence.rel_rms_change[i][m];
            benchmark::RegisterBenchmark("BM_Integration", integration, &material, change)
                ->Arg(convergence.nodes[i])
                ->Unit(benchmark::kMicrosecond);
        }
        benchmark::RunSpecifiedBenchmarks();
        benchmark::Shutdown();
    } catch (const std::exception& e) {
        std::cerr << "metalfit_benchmarks: " << e.what() << "\n";
        return 1;
    }
    return 0;
}
