// Schlick with a linear two-term compensation: F(μ) = F0 + (1 − F0) m⁵ − b₁ μ m⁴ − b₂ μ m⁹, m = 1 − μ, per channel.
// Linear in (F0, b₁, b₂), so its least-squares optimum is solved exactly (target_starts); Ceres only polishes it
// (and handles the bounds). GLSL: schlick_comp_linear.glsl beside this header.
#pragma once

#include <array>
#include <cstddef>
#include <string_view>
#include <vector>

#include "libfit/models/model.hpp"
#include "libfit/models/model_math.hpp"

namespace metalfit::models {

struct SchlickCompLinear {
    static constexpr std::string_view kId = "schlick-comp-linear";
    static constexpr std::string_view kTitle = "Schlick with a linear two-term compensation, b1 mu m^4 + b2 mu m^9";
    static constexpr std::array<Parameter, 3> kParameters{{
        {"F0", -1.0, 2.0, "reflectance at normal incidence (may exceed 1 out of gamut)", ParameterKind::colour},
        {"b1", -20.0, 20.0, "amplitude of mu (1 - mu)^4", ParameterKind::shape},
        {"b2", -20.0, 20.0, "amplitude of mu (1 - mu)^9", ParameterKind::shape},
    }};
    static constexpr std::string_view kGlslFunction = "metalfit_schlick_comp_linear";
    static constexpr std::array<std::string_view, 1> kGlslFiles{"schlick_comp_linear"};
    static constexpr MaterialxForm kMaterialx = MaterialxForm::stand_in;
    static constexpr std::string_view kMaterialxStandIn =
        "a BSDF's Fresnel cannot take mu (1 - mu)^4 and mu (1 - mu)^9 terms";
    // --pin F0: F(1) = F0.
    static constexpr std::size_t kPinnedParameter = 0;
    template <class T>
    static T pinned_value(const T*, const T& F0) {
        return F0;
    }

    template <class T>
    static T evaluate(const T* p, const T& mu_in) {
        const T mu = model_math::clamp_mu(mu_in);
        const T m = T(1) - mu;
        const T m2 = m * m;
        const T m4 = m2 * m2;
        return p[0] + (T(1) - p[0]) * (m4 * m) - mu * m4 * (p[1] + p[2] * (m4 * m));
    }

    // "r1": F0 = R(1), no compensation (Schlick).
    static std::vector<ClosedForm> closed_forms(const ClosedFormInput& input);
    static std::vector<ChannelParameters> neutral_starts() { return {{0.5, 0.0, 0.0}}; }
    // The exact linear least-squares solution of the target in (F0, b1, b2), clamped into the bounds.
    static std::vector<ChannelParameters> target_starts(const ChannelTarget& target);
};

}  // namespace metalfit::models
