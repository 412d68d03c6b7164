#include "exact_real_kernel.hpp"

#include <array>
#include <complex>

#include "libfit/models/registry.hpp"
#include "libfit/optics/fresnel_real.hpp"
#include "opaque.hpp"

namespace metalfit::bench {

EvalKernel exact_real_kernel(const PreparedMaterial& material) {
    const ModelParameters& nk = material.params(models::ConductorRgb::kId);
    std::array<SquaredIndex<float>, 3> eta2;
    for (int c = 0; c < 3; ++c) eta2[c] = squared_index<float>(std::complex<double>(nk[c][0], nk[c][1]));
    EvalKernel k;
    k.id = "exact-real";
    k.kind = "exact";
    k.description = "exact conductor Fresnel, real branch-free form (libfit fresnel_real(), float), conductor-rgb's fitted n,k";
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
        for (int c = 0; c < 3; ++c) {
            const SquaredIndex<float> e = eta2[c];
            float* o = out.data() + c * n;
            for (std::size_t i = 0; i < n; ++i) o[i] = fresnel_real(in[i], e.re, e.re_minus_1, e.im, e.norm2);
        }
    };
    return k;
}

}  // namespace metalfit::bench
