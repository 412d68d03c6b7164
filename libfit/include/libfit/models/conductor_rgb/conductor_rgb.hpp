// Exact conductor Fresnel with one n, k per channel (what most renderers do with measured data).
// GLSL: conductor_rgb.glsl beside this header.
#pragma once

#include <array>
#include <string_view>
#include <vector>

#include "libfit/models/model.hpp"
#include "libfit/models/model_math.hpp"

namespace metalfit::models {

struct ConductorRgb {
    static constexpr std::string_view kId = "conductor-rgb";
    static constexpr std::string_view kTitle = "exact conductor Fresnel with RGB n, k";
    static constexpr std::array<Parameter, 2> kParameters{{
        {"n", 1e-3, 100.0, "refractive index", ParameterKind::index},
        {"k", 0.0, 1e4, "extinction coefficient", ParameterKind::index},
    }};
    static constexpr std::string_view kGlslFunction = "metalfit_conductor_rgb";
    static constexpr std::array<std::string_view, 1> kGlslFiles{"conductor_rgb"};
    static constexpr MaterialxForm kMaterialx = MaterialxForm::conductor_bsdf;
    // --pin F0: F(1) = F0(n, k) = F0 with k² = (F0 (n + 1)² − (n − 1)²) / (1 − F0) for the fitted n (k = 0 below the
    // dielectric F0 of that n; F0 ≥ 1 has no k: the bound, and the record reports the pin as not met).
    static constexpr std::size_t kPinnedParameter = 1;
    template <class T>
    static T pinned_value(const T* p, const T& F0) {
        if (!(F0 < T(1))) return T(kParameters[1].upper);
        const T& n = p[0];
        return model_math::sqrt_or_zero((F0 * (n + T(1)) * (n + T(1)) - (n - T(1)) * (n - T(1))) / (T(1) - F0));
    }

    template <class T>
    static T evaluate(const T* p, const T& mu_in) {
        const T mu = model_math::clamp_mu(mu_in);
        return model_math::conductor_fresnel(p[0], p[1] * p[1], p[0] * p[1], mu);
    }

    // The fits' Jacobian: conductor_fresnel's closed-form gradient in (n, k², nk) with k² = k·k and nk; it agrees
    // with the Jets to rounding, not bit for bit (kGradientTolerance, tests/test_conductor_gradient.cpp).
    static constexpr double kGradientTolerance = 1e-12;
    static double evaluate_with_gradient(const double* p, const model_math::CurveNode& x, double* g) {
        const double n = p[0], k = p[1];
        const model_math::ConductorFresnelGradient F = model_math::conductor_fresnel_gradient(n, k * k, n * k, x.mu);
        g[0] = F.d_n + F.d_nk * k;
        g[1] = F.d_k2 * (2.0 * k) + F.d_nk * n;
        return F.value;
    }

    // "nk-650-550-450" and "nk-700-550-435": n, k of the data sampled at three wavelengths.
    static std::vector<ClosedForm> closed_forms(const ClosedFormInput& input);
    static std::vector<ChannelParameters> neutral_starts() { return {{1.0, 3.0}, {0.2, 3.0}}; }
};

}  // namespace metalfit::models
