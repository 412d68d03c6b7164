// The generalised compensated Schlick: F(μ) = F0 + (1 − F0) mᵖ − a μ m^α, m = 1 − μ, per channel: Schlick's
// exponent 5 becomes a parameter p beside the compensation's amplitude a and exponent α (4 parameters).
// GLSL: schlick_comp_general.glsl beside this header.
#pragma once

#include <array>
#include <cstddef>
#include <string_view>
#include <vector>

#include "libfit/models/compensation_projection.hpp"
#include "libfit/models/model.hpp"
#include "libfit/models/model_math.hpp"

namespace metalfit::models {

struct SchlickCompGeneral {
    static constexpr std::string_view kId = "schlick-comp-general";
    static constexpr std::string_view kTitle = "generalised compensated Schlick, F0 + (1 - F0) m^p - a mu m^alpha";
    static constexpr std::array<Parameter, 4> kParameters{{
        {"F0", -1.0, 2.0, "reflectance at normal incidence (may exceed 1 out of gamut)", ParameterKind::colour},
        {"p", 1.0, 64.0, "exponent of the Schlick term (Schlick: 5)", ParameterKind::shape},
        {"a", -20.0, 20.0, "compensation amplitude", ParameterKind::shape},
        {"alpha", 0.05, 64.0, "compensation exponent", ParameterKind::shape},
    }};
    static constexpr std::string_view kGlslFunction = "metalfit_schlick_comp_general";
    static constexpr std::array<std::string_view, 1> kGlslFiles{"schlick_comp_general"};
    static constexpr MaterialxForm kMaterialx = MaterialxForm::stand_in;
    static constexpr std::string_view kMaterialxStandIn =
        "a BSDF's Fresnel cannot take (1 - mu)^p with free p and mu (1 - mu)^alpha";
    static constexpr std::size_t kPinnedParameter = 0;
    template <class T>
    static T pinned_value(const T*, const T& F0) {
        return F0;
    }

    template <class T>
    static T evaluate(const T* p, const T& mu_in) {
        using std::pow;
        const T mu = model_math::clamp_mu(mu_in);
        const T m = T(1) - mu;
        return p[0] + (T(1) - p[0]) * pow(m, p[1]) - p[2] * mu * pow(m, p[3]);
    }

    // The fits' Jacobian: evaluate's operations as Ceres's Jets carry them, with ln m once per node (mᵖ and m^α
    // cost one pow each instead of the Jets' two pow and a log).
    static double evaluate_with_gradient(const double* p, const model_math::CurveNode& x, double* g) {
        double dp, dalpha;
        const double wp = model_math::node_power(x, p[1], dp), walpha = model_math::node_power(x, p[3], dalpha);
        const double one_minus_F0 = 1.0 - p[0], a_mu = p[2] * x.mu;
        g[0] = 1.0 - wp;
        g[1] = one_minus_F0 * dp;
        g[2] = -(x.mu * walpha);
        g[3] = -(a_mu * dalpha);
        model_math::spread_undefined_derivative(dp, g, 4);
        model_math::spread_undefined_derivative(dalpha, g, 4);
        return p[0] + one_minus_F0 * wp - a_mu * walpha;
    }

    // "r1": F0 = R(1), p = 5, a = 0 (Schlick).
    static std::vector<ClosedForm> closed_forms(const ClosedFormInput& input);
    static std::vector<ChannelParameters> neutral_starts() { return {{0.5, 5.0, 0.0, 6.0}, {0.9, 5.0, 0.3, 2.0}}; }
    // Variable projection: for p on a grid from 1.5 to 64 (18 values) and a log grid of α, (F0, a) solved exactly; the
    // best α of each p, then the 3 best p of the uncompensated curve (a = 0, F0 solved exactly, α = 1).
    static std::vector<ChannelParameters> target_starts(const ChannelTarget& target);
    // The fit by variable projection (ProjectedFit): for fixed (p, α) the curve is linear in F0 and a, solved
    // exactly inside their bounds; the projected residuals are minimised in (p, α) by bounded Levenberg–Marquardt
    // with Kaufman's Jacobian (bounded_levenberg_marquardt).
    class Projection {
    public:
        static constexpr std::array<std::size_t, 2> kNonlinearParameters{1, 3};  // p, α
        explicit Projection(const ChannelTarget& t)
            : surface_(t, {kParameters[0].lower, kParameters[0].upper}, {kParameters[2].lower, kParameters[2].upper}) {}
        std::size_t residuals() const { return surface_.residuals(); }
        bool operator()(const double* z, double* r, double* J) { return surface_(z, r, J); }
        ChannelParameters parameters(const double* nonlinear, const ChannelParameters&) {
            const auto [F0, a] = surface_.linear(nonlinear);
            return {F0, nonlinear[0], a, nonlinear[1]};
        }

    private:
        detail::CompensationSurface surface_;
    };
};

}  // namespace metalfit::models
