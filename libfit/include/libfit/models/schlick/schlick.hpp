// Schlick (1994): F(μ) = F0 + (1 − F0)(1 − μ)^5. GLSL: schlick.glsl beside this header.
#pragma once

#include <array>
#include <string_view>
#include <vector>

#include "libfit/models/model.hpp"
#include "libfit/models/model_math.hpp"

namespace metalfit::models {

struct Schlick {
    static constexpr std::string_view kId = "schlick";
    static constexpr std::string_view kTitle = "Schlick (1994)";
    static constexpr std::array<Parameter, 1> kParameters{{
        {"F0", -1.0, 2.0, "reflectance at normal incidence (may exceed 1 out of gamut)", ParameterKind::colour},
    }};
    static constexpr std::string_view kGlslFunction = "metalfit_schlick";
    static constexpr std::array<std::string_view, 1> kGlslFiles{"schlick"};
    static constexpr MaterialxForm kMaterialx = MaterialxForm::generalized_schlick;
    // Schlick is F82-tint with tint 1.
    static std::array<double, 2> to_f82_tint(const double* p) { return {p[0], 1.0}; }
    // --pin F0: F(1) = F0.
    static constexpr std::size_t kPinnedParameter = 0;
    template <class T>
    static T pinned_value(const T*, const T& F0) {
        return F0;
    }

    template <class T>
    static T evaluate(const T* p, const T& mu_in) {
        const T mu = model_math::clamp_mu(mu_in);
        return p[0] + (T(1) - p[0]) * model_math::schlick_weight(mu);
    }

    // "r1": F0 = R(1).
    static std::vector<ClosedForm> closed_forms(const ClosedFormInput& input);
    static std::vector<ChannelParameters> neutral_starts() { return {{0.5}}; }
};

}  // namespace metalfit::models
