#include "model_kernels.hpp"

#include <algorithm>
#include <array>

#include "libfit/models/registry.hpp"
#include "opaque.hpp"

namespace metalfit::bench {
namespace {

// The most parameters any registered model has.
constexpr std::size_t kMaxParameters = [] {
    std::size_t most = 0;
    for_each_model(Registry{}, [&]<class M>() { most = std::max(most, M::kParameters.size()); });
    return most;
}();
using FloatParams = std::array<std::array<float, kMaxParameters>, 3>;

FloatParams to_float(const ModelParameters& p) {
    FloatParams f{};
    for (int c = 0; c < 3; ++c)
        std::transform(p[c].begin(), p[c].begin() + static_cast<std::ptrdiff_t>(std::min(p[c].size(), kMaxParameters)),
                       f[c].begin(), [](double v) { return static_cast<float>(v); });
    return f;
}

// One channel of M over an array of μ: the loop the compiler vectorises (with -fno-math-errno -fno-trapping-math,
// bench/CMakeLists.txt), M's per-channel constants hoisted out of it. On x86-64 GCC also builds an AVX2 clone, chosen
// at load time (ifunc), for every model alike so that the ratios compare like with like; both clones use the same
// IEEE operations (no FMA), so the values do not depend on the machine (as the reference curve's lanes,
// libfit/src/reference/reference_curve.cpp). The parameters by value: a local copy no store can alias.
template <class M>
#if defined(__x86_64__) && defined(__GNUC__) && !defined(__clang__)
__attribute__((target_clones("avx2", "default")))
#endif
void evaluate_channel(std::array<float, kMaxParameters> parameters, const float* mu, float* out, std::size_t count) {
    for (std::size_t i = 0; i < count; ++i) out[i] = M::evaluate(parameters.data(), mu[i]);
}

template <class M>
EvalKernel model_kernel(const PreparedMaterial& material) {
    static_assert(M::kParameters.size() <= kMaxParameters);
    const FloatParams p = to_float(material.params(M::kId));
    EvalKernel k;
    k.id = std::string(M::kId);
    k.kind = "model";
    k.description = std::string(M::kTitle) + ", float, fitted parameters";
    k.params_per_channel = static_cast<int>(M::kParameters.size());
    k.scalar = [p](std::span<const float> mu, std::span<float> out) {
        for (std::size_t i = 0; i < mu.size(); ++i) {
            float m = mu[i];
            opaque(m);
            out[3 * i + 0] = M::evaluate(p[0].data(), m);
            out[3 * i + 1] = M::evaluate(p[1].data(), m);
            out[3 * i + 2] = M::evaluate(p[2].data(), m);
        }
    };
    k.array = [p](std::span<const float> mu, std::span<float> out) {
        const std::size_t n = mu.size();
        const float* in = mu.data();
        for (int c = 0; c < 3; ++c) evaluate_channel<M>(p[c], in, out.data() + c * n, n);
    };
    return k;
}

}  // namespace

std::vector<EvalKernel> model_kernels(const PreparedMaterial& material) {
    std::vector<EvalKernel> kernels;
    for_each_model(Registry{}, [&]<class M>() { kernels.push_back(model_kernel<M>(material)); });
    return kernels;
}

}  // namespace metalfit::bench
