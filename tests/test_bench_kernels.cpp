// The evaluation kernels the benchmarks time compute what they claim: the models' float evaluation equals the
// runtime Model in double, scalar and array loops agree, the exact complex form equals conductor-rgb, the LUTs
// approach the reference.
#include <gtest/gtest.h>

#include <cmath>

#include "metalfit_bench/catalog_accuracy.hpp"
#include "metalfit_bench/eval_kernels.hpp"
#include "metalfit_bench/reference_lut.hpp"
#include "test_support.hpp"

namespace test_bench_kernels {

using namespace metalfit;
using namespace metalfit::bench;

const Environment& env() {
    static const Environment e = Environment::load(test::kData, std::nullopt);
    return e;
}
const PreparedMaterial& gold() {
    static const PreparedMaterial m = PreparedMaterial::prepare(env(), "Au");
    return m;
}

TEST(BenchKernels, EveryModelAndTheExactFormsAndLutsAreThere) {
    const std::vector<EvalKernel> kernels = eval_kernels(gold());
    std::vector<std::string> ids;
    for (const EvalKernel& k : kernels) ids.push_back(k.id);
    std::vector<std::string> expected;
    for (const Model* m : all_models()) expected.emplace_back(m->id());
    for (const char* extra : {"exact-complex", "exact-real", "lut-64", "lut-256", "spectral-reference"})
        expected.emplace_back(extra);
    EXPECT_EQ(ids, expected);
}

TEST(BenchKernels, ScalarAndArrayLoopsComputeTheModelsAndTheReference) {
    const std::vector<float> mu = bench_mu(64);
    for (const EvalKernel& k : eval_kernels(gold())) {
        std::vector<float> scalar(3 * mu.size()), array(3 * mu.size());
        k.scalar(mu, scalar);
        k.array(mu, array);
        const bool planar = k.id != "spectral-reference";
        for (std::size_t i = 0; i < mu.size(); ++i) {
            const RGB exact = gold().curve(mu[i]);
            for (int c = 0; c < 3; ++c) {
                const float s = scalar[3 * i + c], a = planar ? array[c * mu.size() + i] : array[3 * i + c];
                EXPECT_NEAR(s, a, 1e-6f * std::max(1.0f, std::abs(s))) << k.id << " μ=" << mu[i];
                if (k.kind == "model") {
                    const Model& m = find_model(k.id);
                    EXPECT_NEAR(s, m.evaluate(std::span<const double>(gold().params(k.id)[c]), double(mu[i])), 2e-5)
                        << k.id;
                }
                if (k.id == "exact-complex" || k.id == "exact-real") {
                    const Model& m = find_model("conductor-rgb");
                    EXPECT_NEAR(
                        s, m.evaluate(std::span<const double>(gold().params("conductor-rgb")[c]), double(mu[i])), 2e-5);
                }
                if (k.id == "spectral-reference") {
                    EXPECT_NEAR(s, exact[c], 1e-6);
                }
                if (k.id == "lut-256") {
                    EXPECT_NEAR(s, exact[c], 2e-3);  // linear interpolation, h = 1/255
                }
            }
        }
    }
}

TEST(BenchKernels, LutErrorFallsWithItsSize) {
    const SampledReference reference(gold().curve, env().error);
    const double e64 = worst_channel(ReferenceLut(gold().curve, 64).rel_rms(reference));
    const double e256 = worst_channel(ReferenceLut(gold().curve, 256).rel_rms(reference));
    EXPECT_GT(e64, 0);
    EXPECT_LT(e256, e64 / 4);  // second-order interpolation: 16× in theory, less near the grazing kink
    EXPECT_THROW(ReferenceLut(gold().curve, 1), std::invalid_argument);
}

TEST(BenchKernels, SummaryIsMedianAndWorstIgnoringUndefined) {
    AccuracySummary s{"x", {0.3, NAN, 0.1, 0.2, 0.5}, 0, 0, 0};
    summarise(s);
    EXPECT_DOUBLE_EQ(s.median, 0.25);
    EXPECT_DOUBLE_EQ(s.worst, 0.5);
}

}  // namespace test_bench_kernels
