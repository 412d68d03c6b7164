// F82-tint (Hoffman 2019; Kutz et al. 2021; OpenPBR Surface): F(μ) = F_S(F0, μ) − b μ (1 − μ)^6 with
// b = (1 − t) F_S(F0, μ̄) / (μ̄ (1 − μ̄)^6), μ̄ = 1/7, so F(μ̄) = t F_S(F0, μ̄). GLSL: f82_tint.glsl beside this header.
#pragma once

#include <array>
#include <string_view>
#include <vector>

#include "libfit/models/model.hpp"
#include "libfit/models/model_math.hpp"
#include "libfit/models/schlick/schlick.hpp"

namespace metalfit::models {

struct F82Tint {
    static constexpr std::string_view kId = "f82-tint";
    static constexpr std::string_view kTitle = "F82-tint (Hoffman 2019; OpenPBR specular_color)";
    static constexpr std::array<Parameter, 2> kParameters{{
        {"F0", -1.0, 2.0, "reflectance at normal incidence (OpenPBR base_color)", ParameterKind::colour},
        {"tint", -1.0, 4.0, "F(1/7) / Schlick(F0, 1/7) (OpenPBR specular_color, MaterialX color82)",
         ParameterKind::colour},
    }};
    static constexpr std::string_view kGlslFunction = "metalfit_f82_tint";
    static constexpr std::array<std::string_view, 2> kGlslFiles{"schlick", "f82_tint"};
    static constexpr MaterialxForm kMaterialx = MaterialxForm::generalized_schlick;
    static std::array<double, 2> to_f82_tint(const double* p) { return {p[0], p[1]}; }
    // --pin F0: F(1) = F0.
    static constexpr std::size_t kPinnedParameter = 0;
    template <class T>
    static T pinned_value(const T*, const T& F0) {
        return F0;
    }

    template <class T>
    static T evaluate(const T* p, const T& mu_in) {
        const T mu = model_math::clamp_mu(mu_in);
        constexpr double mu_bar = 1.0 / 7.0;
        constexpr double m_bar = 1.0 - mu_bar;
        constexpr double m6_bar = m_bar * m_bar * m_bar * m_bar * m_bar * m_bar;
        const T m = T(1) - mu;
        const T m3 = m * m * m;
        const T b = (T(1) - p[1]) * Schlick::evaluate(p, T(mu_bar)) / T(mu_bar * m6_bar);
        return Schlick::evaluate(p, mu) - b * (mu * (m3 * m3));
    }

    // "r1-r82": F0 = R(1), t = R(1/7) / F_S(F0, 1/7).
    static std::vector<ClosedForm> closed_forms(const ClosedFormInput& input);
    static std::vector<ChannelParameters> neutral_starts() { return {{0.5, 1.0}}; }
};

}  // namespace metalfit::models
