// Lazányi's error-compensated rescaled Schlick (thesis eq. 3.3): F**(μ) = F*(μ) − a μ (1 − μ)^α.
// GLSL: lazanyi_comp.glsl beside this header (calls ../lazanyi/lazanyi.glsl).
#pragma once

#include <array>
#include <string_view>
#include <vector>

#include "libfit/models/model.hpp"
#include "libfit/models/model_math.hpp"
#include "libfit/models/lazanyi/lazanyi.hpp"

namespace metalfit::models {

struct LazanyiComp {
    static constexpr std::string_view kId = "lazanyi-comp";
    static constexpr std::string_view kTitle = "Lazányi's error-compensated Schlick (thesis eq. 3.3)";
    static constexpr std::array<Parameter, 4> kParameters{{
        Lazanyi::kParameters[0],
        Lazanyi::kParameters[1],
        {"a", -20.0, 20.0, "compensation amplitude (minus the slope of the error at grazing)", ParameterKind::shape},
        {"alpha", 0.05, 64.0, "compensation exponent", ParameterKind::shape},
    }};
    static constexpr std::string_view kGlslFunction = "metalfit_lazanyi_comp";
    static constexpr std::array<std::string_view, 2> kGlslFiles{"lazanyi", "lazanyi_comp"};
    static constexpr MaterialxForm kMaterialx = MaterialxForm::stand_in;
    static constexpr std::string_view kMaterialxStandIn = "a BSDF's Fresnel cannot take mu (1 - mu)^alpha";
    // --pin F0: as Lazányi's (the compensation vanishes at μ = 1).
    static constexpr std::size_t kPinnedParameter = Lazanyi::kPinnedParameter;
    template <class T>
    static T pinned_value(const T* p, const T& F0) { return Lazanyi::pinned_value(p, F0); }

    template <class T>
    static T evaluate(const T* p, const T& mu_in) {
        const T mu = model_math::clamp_mu(mu_in);
        using std::pow;
        return Lazanyi::evaluate(p, mu) - p[2] * mu * pow(T(1) - mu, p[3]);
    }

    // The fits' Jacobian: evaluate's operations as Ceres's Jets carry them (F* = num / den as the Jets divide:
    // num · (1 / den)), with ln m once per node.
    static double evaluate_with_gradient(const double* p, const model_math::CurveNode& x, double* g) {
        const double n = p[0], k = p[1], k2 = k * k, dk2 = k + k;
        const double w5 = model_math::schlick_weight(x.mu);
        const double num = (n - 1.0) * (n - 1.0) + k2 + 4.0 * n * w5, den = (n + 1.0) * (n + 1.0) + k2;
        const double inverse = 1.0 / den, F = num * inverse;
        g[0] = ((2.0 * (n - 1.0) + 4.0 * w5) - F * (2.0 * (n + 1.0))) * inverse;
        g[1] = (dk2 - F * dk2) * inverse;
        double dalpha;
        const double walpha = model_math::node_power(x, p[3], dalpha), a_mu = p[2] * x.mu;
        g[2] = -(x.mu * walpha);
        g[3] = -(a_mu * dalpha);
        model_math::spread_undefined_derivative(dalpha, g, 4);
        return F - a_mu * walpha;
    }

    // The thesis construction on top of each closed form of Lazanyi: a = −d/dμ [R − F*] at μ = 0 (one-sided,
    // second order), α from the match at μ = 0.15. Undefined where a = 0, the logarithm's argument is ≤ 0 or α leaves
    // its bounds (the construction diverges).
    static std::vector<ClosedForm> closed_forms(const ClosedFormInput& input);
    // Variable projection: F** is linear in F0 and a, so for each α of a log-spaced grid over the bounds both are
    // solved exactly (F0 capped at 1); the best few α become starts. Without them Levenberg–Marquardt from the
    // closed forms or neutral starts stops in local minima (gold blue: 1.41 % instead of 1.24 %).
    static std::vector<ChannelParameters> target_starts(const ChannelTarget& target);
    static std::vector<ChannelParameters> neutral_starts() {
        return {{1.0, 3.0, 0.0, 6.0}, {1.0, 3.0, 0.3, 2.0}, {1.0, 3.0, -0.3, 2.0}, {1.0, 3.0, 0.3, 12.0}};
    }
};

}  // namespace metalfit::models
