// Lazányi's error-compensated rescaled Schlick (thesis eq. 3.3): F**(μ) = F*(μ) − a μ (1 − μ)^α.
// GLSL: lazanyi_comp.glsl beside this header (calls ../lazanyi/lazanyi.glsl).
#pragma once

#include <algorithm>
#include <array>
#include <cmath>
#include <string_view>
#include <vector>

#include "libfit/models/lazanyi/lazanyi.hpp"
#include "libfit/models/model.hpp"
#include "libfit/models/model_math.hpp"
#include "libfit/reference/channel_target.hpp"

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
    static T pinned_value(const T* p, const T& F0) {
        return Lazanyi::pinned_value(p, F0);
    }

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
    // The fit by variable projection (ProjectedFit): for fixed α, F** = w + F0 (1 − w) − a μ m^α (w = m⁵, m = 1 − μ,
    // F0 = F0(n, k)) is linear in F0 and a, so F0 ∈ [0, 1] and a ∈ its bounds are solved exactly for every α and
    // the fit is a bounded minimisation of the projected cost in α alone (detail::line_minimum), with its derivative
    // (Golub and Pereyra: at the linear solution the cost is stationary in F0 and a, or they sit on a bound, so
    // dcost/dα is the partial derivative at fixed F0, a). n, k then come from F0 keeping the start's n where some k
    // allows it.
    class Projection {
    public:
        static constexpr std::array<std::size_t, 1> kNonlinearParameters{3};  // α
        explicit Projection(const ChannelTarget& t) {
            for (std::size_t i = 0; i < t.mu.size(); ++i) {
                const double mu = model_math::clamp_mu(t.mu[i]), w = model_math::schlick_weight(mu);
                x1_.push_back(t.scale[i] * (1.0 - w));
                y_.push_back(t.scale[i] * (t.value[i] - w));
                scaled_mu_.push_back(t.scale[i] * mu);
                log_m_.push_back(std::log(1.0 - mu));  // −∞ at μ = 1: m^α = 0 there (α > 0)
                s11_ += x1_.back() * x1_.back();
                s1y_ += x1_.back() * y_.back();
            }
            x2_.resize(x1_.size());
            r_.resize(x1_.size());
        }
        std::size_t residuals() const { return x1_.size(); }

        // residual_i = x1_i F0 + x2_i a − y_i with x1 = s (1 − w), x2 = −s μ m^α, y = s (R − w), at the solution.
        void residuals(double alpha, double* r) const {
            double F0, a;
            std::vector<double> x2(residuals());
            solve(alpha, F0, a, x2.data(), r);
        }

        // The projected cost ½ Σ r² at α and its derivative: a Σ r_i ∂x2_i/∂α = a Σ r_i x2_i ln m_i.
        struct Point {
            double cost, slope;
        };
        Point at(double alpha) {
            double F0, a;
            solve(alpha, F0, a, x2_.data(), r_.data());
            double cost = 0, slope = 0;
            for (std::size_t i = 0; i < r_.size(); ++i) {
                cost += 0.5 * r_[i] * r_[i];
                if (!std::isinf(log_m_[i])) slope += r_[i] * x2_[i] * log_m_[i];
            }
            return {cost, a * slope};
        }

        // The normal equations of F0 and a at α: Σ x1², Σ x1 x2, Σ x2², Σ x1 y, Σ x2 y (x2 written into x2, one
        // value a residual). Also what target_starts solves on its grid of α.
        struct NormalEquations {
            double s11, s12, s22, s1y, s2y;
        };
        NormalEquations normal_equations(double alpha, double* x2) const {
            double s12 = 0.0, s22 = 0.0, s2y = 0.0;
            for (std::size_t i = 0; i < x1_.size(); ++i) {
                x2[i] = std::isinf(log_m_[i]) ? 0.0 : -scaled_mu_[i] * std::exp(alpha * log_m_[i]);
                s12 += x2[i] * x1_[i], s22 += x2[i] * x2[i], s2y += x2[i] * y_[i];
            }
            return {s11_, s12, s22, s1y_, s2y};
        }

        // The full parameters at α: F0 and a solved, n, k from F0 (the start's n kept where some k ≥ 0 gives F0).
        ChannelParameters parameters(const double* nonlinear, const ChannelParameters& start) const {
            double F0 = 0, a = 0;
            std::vector<double> x2(residuals()), r(residuals());
            solve(nonlinear[0], F0, a, x2.data(), r.data());
            ChannelParameters p = Lazanyi::nk_near(F0, start[0]);
            p.push_back(a);
            p.push_back(nonlinear[0]);
            return p;
        }

    private:
        void solve(double alpha, double& F0, double& a, double* x2, double* residuals) const {
            const auto& a_bounds = kParameters[2];
            const auto [s11, s12, s22, s1y, s2y] = normal_equations(alpha, x2);
            const double det = s11 * s22 - s12 * s12;
            if (det > 0.0) {
                F0 = (s22 * s1y - s12 * s2y) / det;
                a = (s11 * s2y - s12 * s1y) / det;
            } else {
                F0 = s1y / s11, a = 0.0;
            }
            // F0(n, k) ∈ [0, 1); a in its bounds: the bound held, the other solved again.
            if (F0 > 1.0 || F0 < 0.0) {
                F0 = F0 > 1.0 ? 1.0 : 0.0;
                a = s22 > 0.0 ? (s2y - s12 * F0) / s22 : 0.0;
            }
            if (a > a_bounds.upper || a < a_bounds.lower) {
                a = a > a_bounds.upper ? a_bounds.upper : a_bounds.lower;
                F0 = std::clamp((s1y - s12 * a) / s11, 0.0, 1.0);
            }
            for (std::size_t i = 0; i < x1_.size(); ++i) residuals[i] = x1_[i] * F0 + x2[i] * a - y_[i];
        }

        std::vector<double> x1_, y_, scaled_mu_, log_m_;
        std::vector<double> x2_, r_;  // at(): scratch
        double s11_ = 0, s1y_ = 0;
    };

    static std::vector<ChannelParameters> neutral_starts() {
        return {{1.0, 3.0, 0.0, 6.0}, {1.0, 3.0, 0.3, 2.0}, {1.0, 3.0, -0.3, 2.0}, {1.0, 3.0, 0.3, 12.0}};
    }
};

}  // namespace metalfit::models
