#include "metalfit_bench/eval_kernels.hpp"

#include <algorithm>
#include <array>
#include <memory>
#include <random>

#include "exact_real_kernel.hpp"
#include "libfit/models/registry.hpp"
#include "libfit/optics/fresnel.hpp"
#include "metalfit_bench/reference_lut.hpp"
#include "model_kernels.hpp"
#include "opaque.hpp"

namespace metalfit::bench {
namespace {

EvalKernel exact_complex_kernel(const PreparedMaterial& material) {
    const ModelParameters& nk = material.params(models::ConductorRgb::kId);
    const std::array<std::complex<double>, 3> eta{std::complex<double>(nk[0][0], nk[0][1]),
                                                  std::complex<double>(nk[1][0], nk[1][1]),
                                                  std::complex<double>(nk[2][0], nk[2][1])};
    EvalKernel k;
    k.id = "exact-complex";
    k.kind = "exact";
    k.description = "exact conductor Fresnel, complex form (libfit fresnel(), double), conductor-rgb's fitted n,k";
    k.params_per_channel = 2;
    k.scalar = [eta](std::span<const float> mu, std::span<float> out) {
        for (std::size_t i = 0; i < mu.size(); ++i) {
            float m = mu[i];
            opaque(m);
            for (int c = 0; c < 3; ++c) out[3 * i + c] = static_cast<float>(fresnel(m, eta[c]));
        }
    };
    k.array = [eta](std::span<const float> mu, std::span<float> out) {
        const std::size_t n = mu.size();
        for (int c = 0; c < 3; ++c)
            for (std::size_t i = 0; i < n; ++i) out[c * n + i] = static_cast<float>(fresnel(mu[i], eta[c]));
    };
    return k;
}

EvalKernel lut_kernel(const PreparedMaterial& material, int entries) {
    const auto lut = std::make_shared<const ReferenceLut>(material.curve, entries);
    EvalKernel k;
    k.id = "lut-" + std::to_string(entries);
    k.kind = "lut";
    k.description =
        "1D table of the exact curve, " + std::to_string(entries) + " float RGB entries, linear interpolation";
    k.params_per_channel = entries;
    k.scalar = [lut](std::span<const float> mu, std::span<float> out) {
        for (std::size_t i = 0; i < mu.size(); ++i) {
            float m = mu[i];
            opaque(m);
            const std::array<float, 3> v = (*lut)(m);
            out[3 * i + 0] = v[0];
            out[3 * i + 1] = v[1];
            out[3 * i + 2] = v[2];
        }
    };
    k.array = [lut](std::span<const float> mu, std::span<float> out) {
        const std::size_t n = mu.size();
        const ReferenceLut& t = *lut;
        for (std::size_t i = 0; i < n; ++i) {
            const std::array<float, 3> v = t(mu[i]);
            out[i] = v[0];
            out[n + i] = v[1];
            out[2 * n + i] = v[2];
        }
    };
    return k;
}

EvalKernel spectral_kernel(const PreparedMaterial& material) {
    const ReferenceCurve* curve = &material.curve;
    EvalKernel k;
    k.id = "spectral-reference";
    k.kind = "exact";
    k.description =
        "exact spectral reference: complex Fresnel at 471 wavelengths x CMF x D65, OCIO, white balance (double)";
    k.batch = 16;
    const auto run = [curve](std::span<const float> mu, std::span<float> out) {
        for (std::size_t i = 0; i < mu.size(); ++i) {
            const RGB v = (*curve)(mu[i]);
            for (int c = 0; c < 3; ++c) out[3 * i + c] = static_cast<float>(v[c]);
        }
    };
    k.scalar = run;
    k.array = run;  // one μ at a time either way: 471 wavelengths per μ
    return k;
}

}  // namespace

std::vector<EvalKernel> eval_kernels(const PreparedMaterial& material) {
    std::vector<EvalKernel> kernels = model_kernels(material);
    kernels.push_back(exact_complex_kernel(material));
    kernels.push_back(exact_real_kernel(material));
    kernels.push_back(lut_kernel(material, 64));
    kernels.push_back(lut_kernel(material, 256));
    kernels.push_back(spectral_kernel(material));
    return kernels;
}

std::vector<float> bench_mu(std::size_t count) {
    std::vector<float> mu(count);
    for (std::size_t i = 0; i < count; ++i) mu[i] = static_cast<float>(i + 1) / static_cast<float>(count);
    std::mt19937 rng(20240601u);
    std::shuffle(mu.begin(), mu.end(), rng);
    return mu;
}

}  // namespace metalfit::bench
