#include "exact_real_kernel.hpp"

#include <array>
#include <complex>

#include "libfit/models/registry.hpp"
#include "libfit/optics/fresnel_real.hpp"
#include "opaque.hpp"

namespace metalfit::bench {

namespace {

// One channel over an array of μ, with an AVX2 clone as the model kernels have (model_kernels.cpp).
#if defined(__x86_64__) && defined(__GNUC__) && !defined(__clang__)
__attribute__((target_clones("avx2", "default")))
#endif
void evaluate_channel(SquaredIndex<float> e, const float* mu, float* out, std::size_t count) {
    for (std::size_t i = 0; i < count; ++i) out[i] = fresnel_real(mu[i], e.re, e.re_minus_1, e.im, e.norm2);
}

}  // namespace

EvalKernel exact_real_kernel(const PreparedMaterial& material) {
    const ModelParameters& nk = material.params(models::ConductorRgb::kId);
    std::array<SquaredIndex<float>, 3> eta2;
    for (int c = 0; c < 3; ++c) eta2[c] = squared_index<float>(std::complex<double>(nk[c][0], nk[c][1]));
    EvalKernel k;
    k.id = "exact-real";
    k.kind = "exact";
    k.description =
        "exact conductor Fresnel, real branch-free form (libfit fresnel_real(), float), conductor-rgb's fitted n,k";
    k.params_per_channel = 2;
    k.scalar = [eta2](std::span<const float> mu, std::span<float> out) {
        for (std::size_t i = 0; i < mu.size(); ++i) {
            float m = mu[i];
            opaque(m);
            for (int c = 0; c < 3; ++c) out[3 * i + c] = fresnel_real(m, eta2[c]);
        }
    };
    k.array = [eta2](std::span<const float> mu, std::span<float> out) {
        const std::size_t n = mu.size();
        const float* in = mu.data();
        for (int c = 0; c < 3; ++c) evaluate_channel(eta2[c], in, out.data() + c * n, n);
    };
    return k;
}

}  // namespace metalfit::bench
