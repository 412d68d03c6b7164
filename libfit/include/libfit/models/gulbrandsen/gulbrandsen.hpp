// Gulbrandsen (2014) artist-friendly metallic Fresnel (MaterialX artistic_ior): reflectivity r and edge tint g
// per channel, mapped to n, k and the exact conductor Fresnel. GLSL: gulbrandsen.glsl beside this header.
#pragma once

#include <array>
#include <complex>
#include <string_view>
#include <vector>

#include "libfit/models/model.hpp"
#include "libfit/models/model_math.hpp"

namespace metalfit::models {

struct Gulbrandsen {
    static constexpr std::string_view kId = "gulbrandsen";
    static constexpr std::string_view kTitle = "Gulbrandsen (2014) reflectivity + edge tint";
    static constexpr std::array<Parameter, 2> kParameters{{
        {"r", 0.0, 0.99999, "reflectivity (F0)", ParameterKind::colour},
        {"g", 0.0, 1.0, "edge tint", ParameterKind::colour},
    }};
    static constexpr std::string_view kGlslFunction = "metalfit_gulbrandsen";
    static constexpr std::array<std::string_view, 2> kGlslFiles{"conductor_rgb", "gulbrandsen"};
    static constexpr MaterialxForm kMaterialx = MaterialxForm::artistic_ior;
    // --pin F0: F(1) = r.
    static constexpr std::size_t kPinnedParameter = 0;
    template <class T>
    static T pinned_value(const T*, const T& F0) {
        return F0;
    }

    // n = g n_min + (1 − g) n_max with n_min = (1 − r)/(1 + r), n_max = (1 + √r)/(1 − √r).
    template <class T>
    static T n_of(const T& r, const T& g) {
        const T sr = model_math::sqrt_or_zero(r);
        return g * ((T(1) - r) / (T(1) + r)) + (T(1) - g) * ((T(1) + sr) / (T(1) - sr));
    }
    // Gulbrandsen's k² = (r (n + 1)² − (n − 1)²) / (1 − r), factored as (n_max − n)(n − n₋) with
    // n₋ = (1 − √r)/(1 + √r) and n_max − n = g (n_max − n_min): exactly 0 at g = 0 with the right derivative (the
    // unfactored form cancels to ±1e-16 there and a clamp would drop dk²/dg). Held at 0 below n₋ (g far above 1).
    template <class T>
    static T k2_of(const T& r, const T& g) {
        const T sr = model_math::sqrt_or_zero(r);
        const T n_max = (T(1) + sr) / (T(1) - sr);
        const T n_min = (T(1) - r) / (T(1) + r);
        const T n_minus = (T(1) - sr) / (T(1) + sr);
        const T k2 = g * (n_max - n_min) * (n_of(r, g) - n_minus);
        return k2 >= T(0) ? k2 : T(0);
    }

    template <class T>
    static T evaluate(const T* p, const T& mu_in) {
        const T mu = model_math::clamp_mu(mu_in);
        const T n = n_of(p[0], p[1]);
        const T k2 = k2_of(p[0], p[1]);
        return model_math::conductor_fresnel(n, k2, n * model_math::sqrt_or_zero(k2), mu);
    }

    // The fits' Jacobian: n_of, k2_of and nk = n √k² with their derivatives in (r, g), then conductor_fresnel's
    // closed-form gradient; the same values as evaluate, the derivatives of the Jets to rounding (kGradientTolerance,
    // tests/test_conductor_gradient.cpp). Where a square root's argument or the unclamped k² is ≤ 0 or < 0, its
    // derivative is 0, as the Jets take sqrt_or_zero and the clamp.
    static constexpr double kGradientTolerance = 1e-12;
    static double evaluate_with_gradient(const double* p, const model_math::CurveNode& x, double* grad) {
        const double r = p[0], g = p[1];
        const double sr = model_math::sqrt_or_zero(r);
        const double sr_r = sr > 0.0 ? 0.5 / sr : 0.0;
        const double n_min = (1.0 - r) / (1.0 + r), n_max = (1.0 + sr) / (1.0 - sr), n_minus = (1.0 - sr) / (1.0 + sr);
        const double n_min_r = -2.0 / ((1.0 + r) * (1.0 + r));
        const double n_max_r = 2.0 / ((1.0 - sr) * (1.0 - sr)) * sr_r;
        const double n_minus_r = -2.0 / ((1.0 + sr) * (1.0 + sr)) * sr_r;
        const double n = g * n_min + (1.0 - g) * n_max;  // n_of
        const double n_r = g * n_min_r + (1.0 - g) * n_max_r, n_g = n_min - n_max;
        const double k2_unclamped = g * (n_max - n_min) * (n - n_minus);  // k2_of
        const bool k2_held = !(k2_unclamped >= 0.0);
        const double k2 = k2_held ? 0.0 : k2_unclamped;
        const double k2_r =
            k2_held ? 0.0 : g * ((n_max_r - n_min_r) * (n - n_minus) + (n_max - n_min) * (n_r - n_minus_r));
        const double k2_g = k2_held ? 0.0 : (n_max - n_min) * (n - n_minus) + g * (n_max - n_min) * n_g;
        const double k = model_math::sqrt_or_zero(k2);
        const double k_of_k2 = k > 0.0 ? 0.5 / k : 0.0;  // dk/dk²
        const double nk = n * k;
        const double nk_r = n_r * k + n * k_of_k2 * k2_r, nk_g = n_g * k + n * k_of_k2 * k2_g;
        const model_math::ConductorFresnelGradient F = model_math::conductor_fresnel_gradient(n, k2, nk, x.mu);
        grad[0] = F.d_n * n_r + F.d_k2 * k2_r + F.d_nk * nk_r;
        grad[1] = F.d_n * n_g + F.d_k2 * k2_g + F.d_nk * nk_g;
        return F.value;
    }

    // The inverse: r = ((n − 1)² + k²)/((n + 1)² + k²), g = (n_max − n)/(n_max − n_min) (g = 0 when r = 0).
    static std::array<double, 2> from_nk(std::complex<double> eta);
    static std::complex<double> to_nk(double r, double g);

    // "nk-650-550-450" and "nk-700-550-435": the data's n, k at three wavelengths mapped to r, g.
    static std::vector<ClosedForm> closed_forms(const ClosedFormInput& input);
    static std::vector<ChannelParameters> neutral_starts() { return {{0.5, 0.5}}; }
    // The curves are conductor-rgb's: its fit (n, k) mapped to (r, g) is the first start (the optimum itself where it
    // maps inside the bounds).
    static constexpr std::string_view kStartsFrom = "conductor-rgb";
    static ChannelParameters start_from(const ChannelParameters& nk) {
        const auto rg = from_nk({nk[0], nk[1]});
        return {rg[0], rg[1]};
    }
};

}  // namespace metalfit::models
