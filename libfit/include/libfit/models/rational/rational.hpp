// A rational curve per channel: F(μ) = (1 + a μ + b μ²) / (1 + c μ + d μ²), F(0) = 1 built in, F(1) =
// (1 + a + b) / (1 + c + d). No power and no square root: two multiply-adds each side and one division, the
// cheapest shader form with four parameters; it follows metals' dip near grazing that Schlick's family only
// approximates. Its parameters are shape parameters (no colour: the gamut policy cannot adjust them).
// GLSL: rational.glsl beside this header.
#pragma once

#include <algorithm>
#include <array>
#include <cstddef>
#include <string>
#include <string_view>
#include <vector>

#include "libfit/models/model.hpp"
#include "libfit/models/model_math.hpp"
#include "libfit/models/two_column_projection.hpp"
#include "libfit/reference/channel_target.hpp"

namespace metalfit::models {

struct Rational {
    static constexpr std::string_view kId = "rational";
    static constexpr std::string_view kTitle = "rational (1 + a mu + b mu^2) / (1 + c mu + d mu^2)";
    static constexpr std::array<Parameter, 4> kParameters{{
        {"a", -1e4, 1e4, "numerator, coefficient of mu", ParameterKind::shape},
        {"b", -1e4, 1e4, "numerator, coefficient of mu^2", ParameterKind::shape},
        {"c", -1e4, 1e4, "denominator, coefficient of mu", ParameterKind::shape},
        {"d", -1e4, 1e4, "denominator, coefficient of mu^2", ParameterKind::shape},
    }};
    static constexpr std::string_view kGlslFunction = "metalfit_rational";
    static constexpr std::array<std::string_view, 1> kGlslFiles{"rational"};
    static constexpr MaterialxForm kMaterialx = MaterialxForm::stand_in;
    static constexpr std::string_view kMaterialxStandIn = "a BSDF's Fresnel cannot take a rational function of mu";
    // --pin F0: b = F0 (1 + c + d) − 1 − a.
    static constexpr std::size_t kPinnedParameter = 1;
    template <class T>
    static T pinned_value(const T* p, const T& F0) {
        return F0 * (T(1) + p[2] + p[3]) - T(1) - p[0];
    }

    template <class T>
    static T evaluate(const T* p, const T& mu_in) {
        const T mu = model_math::clamp_mu(mu_in);
        return (T(1) + mu * (p[0] + p[1] * mu)) / (T(1) + mu * (p[2] + p[3] * mu));
    }

    // A root of the denominator 1 + c mu + d mu^2 in [0, 1] is a pole of the curve there (η ≈ 1 drives the fit to
    // one: ±8e6 and non-finite values at the root): such parameters are discarded by the fit (docs/fitting.md).
    // The denominator is 1 at mu = 0; its minimum on [0, 1] is at mu = 1 or at its vertex -c / (2d) when d > 0.
    static double denominator_minimum(const double* p) {
        double minimum = std::min(1.0, 1.0 + p[2] + p[3]);
        if (p[3] > 0) {
            const double vertex = -p[2] / (2 * p[3]);
            if (vertex > 0 && vertex < 1) minimum = std::min(minimum, 1.0 + vertex * (p[2] + p[3] * vertex));
        }
        return minimum;
    }
    static std::string inadmissible(const double* p);  // rational.cpp

    // None: no parameter is a property of the data at one angle.
    static std::vector<ClosedForm> closed_forms(const ClosedFormInput&) { return {}; }
    // The constant 1 written with denominators of growing weight (the fits of metals range from c, d ≈ 1 to ≈ 300:
    // copper's red of McPeak needs c ≈ 36, d ≈ 135, which LM does not reach from c = d = 0).
    static std::vector<ChannelParameters> neutral_starts() {
        return {{0.0, 0.0, 0.0, 0.0}, {3.0, 3.0, 3.0, 3.0}, {30.0, 30.0, 30.0, 30.0}, {30.0, 300.0, 30.0, 300.0}};
    }
    // Linearised least squares (Levy): R (1 + c μ + d μ²) − (1 + a μ + b μ²) ≈ 0 is linear in (a, b, c, d); then
    // Sanathanan–Koerner reweighting by the previous denominator (each iterate is a start).
    static std::vector<ChannelParameters> target_starts(const ChannelTarget& target);
    // The fit by variable projection (ProjectedFit): for fixed (c, d) the curve is linear in a and b, solved exactly
    // inside their bounds (columns s μ / D, s μ² / D, right-hand side s (R − 1 / D), D = 1 + c μ + d μ²); the
    // projected residuals are minimised in (c, d) by bounded Levenberg–Marquardt with Kaufman's Jacobian. A (c, d)
    // with D ≤ 0 at a node cannot be evaluated (a pole between the nodes before it: never a curve).
    class Projection {
    public:
        static constexpr std::array<std::size_t, 2> kNonlinearParameters{2, 3};  // c, d
        explicit Projection(const ChannelTarget& t);
        std::size_t residuals() const { return mu_.size(); }
        bool operator()(const double* z, double* r, double* J);  // rational.cpp
        ChannelParameters parameters(const double* nonlinear, const ChannelParameters&);

    private:
        bool solve(const double* z, detail::TwoColumnSolution& solution);
        std::vector<double> mu_, scale_, value_, inverse_d_, x1_, x2_, y_, r_;
    };
};

}  // namespace metalfit::models
