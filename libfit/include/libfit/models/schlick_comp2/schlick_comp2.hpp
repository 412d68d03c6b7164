// Schlick with a two-term compensation (the accuracy issue's family, linear in b₁, b₂):
// F(μ) = F0 + (1 − F0) m⁵ − b₁ μ m⁴ − b₂ μ m⁹, m = 1 − μ. GLSL: schlick_comp2.glsl beside this header.
#pragma once

#include <array>
#include <string_view>
#include <vector>

#include "libfit/models/model.hpp"
#include "libfit/models/model_math.hpp"

namespace metalfit::models {

struct SchlickComp2 {
    static constexpr std::string_view kId = "schlick-comp2";
    static constexpr std::string_view kTitle = "Schlick with two compensation terms, mu m^4 and mu m^9";
    static constexpr std::array<Parameter, 3> kParameters{{
        {"F0", -1.0, 2.0, "reflectance at normal incidence (may exceed 1 out of gamut)", ParameterKind::colour},
        {"b1", -20.0, 20.0, "amplitude of mu (1 - mu)^4", ParameterKind::shape},
        {"b2", -20.0, 20.0, "amplitude of mu (1 - mu)^9", ParameterKind::shape},
    }};
    static constexpr std::string_view kGlslFunction = "metalfit_schlick_comp2";
    static constexpr std::array<std::string_view, 1> kGlslFiles{"schlick_comp2"};
    static constexpr MaterialxForm kMaterialx = MaterialxForm::stand_in;
    static constexpr std::string_view kMaterialxStandIn = "a BSDF's Fresnel cannot take mu (1 - mu)^4 and mu (1 - mu)^9 terms";

    template <class T>
    static T evaluate(const T* p, const T& mu) {
        const T m = T(1) - mu;
        const T m2 = m * m;
        const T m4 = m2 * m2;
        return p[0] + (T(1) - p[0]) * (m4 * m) - mu * m4 * (p[1] + p[2] * (m4 * m));
    }

    // "r1": F0 = R(1), no compensation (Schlick).
    static std::vector<ClosedForm> closed_forms(const ClosedFormInput& input);
    static std::vector<ChannelParameters> neutral_starts() { return {{0.5, 0.0, 0.0}}; }
};

}  // namespace metalfit::models
