// Lazányi's error compensation on a plain Schlick with F0 free: F(μ) = F0 + (1 − F0) m⁵ − a μ m^α, m = 1 − μ, per
// channel. Lazányi's compensated form (lazanyi-comp) ties F0 to F0(n, k) < 1; here F0 is a colour like Schlick's and
// may exceed 1 (gold's red in Linear Rec.709), which removes lazanyi-comp's kink at normal incidence on gold.
// GLSL: schlick_comp.glsl beside this header.
#pragma once

#include <array>
#include <cstddef>
#include <string_view>
#include <vector>

#include "libfit/models/compensation_projection.hpp"
#include "libfit/models/model.hpp"
#include "libfit/models/model_math.hpp"

namespace metalfit::models {

struct SchlickComp {
    static constexpr std::string_view kId = "schlick-comp";
    static constexpr std::string_view kTitle = "Schlick with Lazanyi's compensation a mu (1 - mu)^alpha, F0 free";
    static constexpr std::array<Parameter, 3> kParameters{{
        {"F0", -1.0, 2.0, "reflectance at normal incidence (may exceed 1 out of gamut)", ParameterKind::colour},
        {"a", -20.0, 20.0, "compensation amplitude", ParameterKind::shape},
        {"alpha", 0.05, 64.0, "compensation exponent", ParameterKind::shape},
    }};
    static constexpr std::string_view kGlslFunction = "metalfit_schlick_comp";
    static constexpr std::array<std::string_view, 1> kGlslFiles{"schlick_comp"};
    static constexpr MaterialxForm kMaterialx = MaterialxForm::stand_in;
    static constexpr std::string_view kMaterialxStandIn = "a BSDF's Fresnel cannot take mu (1 - mu)^alpha";
    static constexpr std::size_t kPinnedParameter = 0;
    template <class T>
    static T pinned_value(const T*, const T& F0) {
        return F0;
    }

    template <class T>
    static T evaluate(const T* p, const T& mu_in) {
        using std::pow;
        const T mu = model_math::clamp_mu(mu_in);
        return p[0] + (T(1) - p[0]) * model_math::schlick_weight(mu) - p[1] * mu * pow(T(1) - mu, p[2]);
    }

    // The fits' Jacobian: evaluate's operations as Ceres's Jets carry them, with ln m once per node.
    static double evaluate_with_gradient(const double* p, const model_math::CurveNode& x, double* g) {
        double dalpha;
        const double w5 = model_math::schlick_weight(x.mu), walpha = model_math::node_power(x, p[2], dalpha);
        const double a_mu = p[1] * x.mu;
        g[0] = 1.0 - w5;
        g[1] = -(x.mu * walpha);
        g[2] = -(a_mu * dalpha);
        model_math::spread_undefined_derivative(dalpha, g, 3);
        return p[0] + (1.0 - p[0]) * w5 - a_mu * walpha;
    }

    // "r1": F0 = R(1), a = 0 (Schlick).
    static std::vector<ClosedForm> closed_forms(const ClosedFormInput& input);
    static std::vector<ChannelParameters> neutral_starts() { return {{0.5, 0.0, 6.0}, {0.9, 0.3, 2.0}}; }
    // Variable projection: for each α of a log grid over its bounds, (F0, a) solved exactly; the best few α.
    static std::vector<ChannelParameters> target_starts(const ChannelTarget& target);
    // The fit by variable projection (ProjectedFit), as lazanyi-comp's: for fixed α the curve is linear in F0 and a,
    // solved exactly inside their bounds, and the projected cost is minimised in α alone (detail::line_minimum).
    class Projection {
    public:
        static constexpr std::array<std::size_t, 1> kNonlinearParameters{2};  // α
        explicit Projection(const ChannelTarget& t)
            : line_(t, 5.0, {kParameters[0].lower, kParameters[0].upper},
                    {kParameters[1].lower, kParameters[1].upper}) {}
        std::size_t residuals() const { return line_.residuals(); }
        detail::CompensationLine::Point at(double alpha) { return line_.at(alpha); }
        ChannelParameters parameters(const double* nonlinear, const ChannelParameters&) {
            const auto [F0, a] = line_.linear(nonlinear[0]);
            return {F0, a, nonlinear[0]};
        }

    private:
        detail::CompensationLine line_;
    };
};

}  // namespace metalfit::models
