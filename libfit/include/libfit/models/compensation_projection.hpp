// Variable projection for the compensated Schlick families F0 + (1 − F0) mᵖ − a μ m^α, m = 1 − μ: for fixed p and α
// the curve is linear in (F0, a), solved exactly inside their bounds (`two_column_fit`); what is left is
// a problem in α alone (schlick-comp: `CompensationLine`, p = 5) or in (p, α) (schlick-comp-general:
// `CompensationSurface`), and a grid over α (and p) ranks the starts (`compensation_candidates`).
#pragma once

#include <algorithm>
#include <array>
#include <cmath>
#include <cstddef>
#include <limits>
#include <vector>

#include "libfit/models/model.hpp"
#include "libfit/models/model_math.hpp"
#include "libfit/models/two_column_projection.hpp"

namespace metalfit::detail {

// The columns of a compensated Schlick at the nodes of a channel's target, scaled by its residual weights:
// x₁ = s (1 − mᵖ), x₂ = −s μ m^α, y = s (R − mᵖ), so that r = F0 x₁ + a x₂ − y = s (F(μ) − R(μ)).
class CompensationColumns {
public:
    CompensationColumns(const ChannelTarget& t, std::array<double, 2> F0_bounds, std::array<double, 2> a_bounds)
        : lower_{F0_bounds[0], a_bounds[0]}, upper_{F0_bounds[1], a_bounds[1]} {
        for (std::size_t i = 0; i < t.mu.size(); ++i) {
            const double mu = model_math::clamp_mu(t.mu[i]);
            scale_.push_back(t.scale[i]);
            scaled_mu_.push_back(t.scale[i] * mu);
            value_.push_back(t.value[i]);
            log_m_.push_back(std::log(1.0 - mu));  // −∞ at μ = 1: every power of m is 0 there
        }
        const std::size_t n = scale_.size();
        m_power_.resize(n), m_alpha_.resize(n), x1_.resize(n), x2_.resize(n), y_.resize(n), r_.resize(n);
    }
    std::size_t residuals() const { return scale_.size(); }

    // mᵖ and m^α at every node, the columns, and (F0, a) solved: residuals in r().
    TwoColumnSolution solve(double power, double alpha) {
        for (std::size_t i = 0; i < scale_.size(); ++i) {
            const double lm = log_m_[i];
            m_power_[i] = std::isinf(lm) ? 0.0 : std::exp(power * lm);
            m_alpha_[i] = std::isinf(lm) ? 0.0 : std::exp(alpha * lm);
            x1_[i] = scale_[i] * (1.0 - m_power_[i]);
            x2_[i] = -scaled_mu_[i] * m_alpha_[i];
            y_[i] = scale_[i] * (value_[i] - m_power_[i]);
        }
        return two_column_fit(x1_, x2_, y_, lower_, upper_, r_.data());
    }
    // After solve(): ∂r/∂p and ∂r/∂α at fixed (F0, a), projected onto the complement of the free columns
    // (Kaufman's variable-projection Jacobian: its Jᵀ r is the projected cost's exact gradient, r being orthogonal to
    // the free columns), written at stride `stride` from `column` (0: p, 1: α; a negative column skips it).
    void jacobian(const TwoColumnSolution& s, int p_column, int alpha_column, int stride, double* J) const {
        const std::size_t n = scale_.size();
        const double F0 = s.c[0], a = s.c[1];
        for (std::size_t i = 0; i < n; ++i) {
            const double lm = std::isinf(log_m_[i]) ? 0.0 : log_m_[i];
            if (p_column >= 0) J[i * stride + p_column] = scale_[i] * (1.0 - F0) * m_power_[i] * lm;
            if (alpha_column >= 0) J[i * stride + alpha_column] = -a * scaled_mu_[i] * m_alpha_[i] * lm;
        }
        project_out_free_columns(x1_, x2_, s.free, {p_column, alpha_column}, stride, J);
    }
    const std::vector<double>& r() const { return r_; }
    const std::vector<double>& x2() const { return x2_; }
    double log_m(std::size_t i) const { return log_m_[i]; }

private:
    std::array<double, 2> lower_, upper_;
    std::vector<double> scale_, scaled_mu_, value_, log_m_;
    std::vector<double> m_power_, m_alpha_, x1_, x2_, y_, r_;
};

// schlick-comp (p = 5): the projected cost in α alone and its derivative a Σ rᵢ x₂ᵢ ln mᵢ (at the solution the cost
// is stationary in F0 and a, or they sit on a bound), for line_minimum.
class CompensationLine {
public:
    CompensationLine(const ChannelTarget& t, double power, std::array<double, 2> F0_bounds,
                     std::array<double, 2> a_bounds)
        : columns_(t, F0_bounds, a_bounds), power_(power) {}
    std::size_t residuals() const { return columns_.residuals(); }
    struct Point {
        double cost, slope;
    };
    Point at(double alpha) {
        const TwoColumnSolution s = columns_.solve(power_, alpha);
        double cost = 0, slope = 0;
        const auto& r = columns_.r();
        const auto& x2 = columns_.x2();
        for (std::size_t i = 0; i < r.size(); ++i) {
            cost += 0.5 * r[i] * r[i];
            if (!std::isinf(columns_.log_m(i))) slope += r[i] * x2[i] * columns_.log_m(i);
        }
        return {cost, s.c[1] * slope};
    }
    // (F0, a) at α.
    std::array<double, 2> linear(double alpha) { return columns_.solve(power_, alpha).c; }

private:
    CompensationColumns columns_;
    double power_;
};

// schlick-comp-general: the projected residuals in (p, α) and Kaufman's Jacobian, for bounded_levenberg_marquardt.
class CompensationSurface {
public:
    CompensationSurface(const ChannelTarget& t, std::array<double, 2> F0_bounds, std::array<double, 2> a_bounds)
        : columns_(t, F0_bounds, a_bounds) {}
    std::size_t residuals() const { return columns_.residuals(); }
    // z = (p, α); r and J (n × 2, row-major). False where a value is not finite.
    bool operator()(const double* z, double* r, double* J) {
        const TwoColumnSolution s = columns_.solve(z[0], z[1]);
        columns_.jacobian(s, 0, 1, 2, J);
        const auto& residual = columns_.r();
        for (std::size_t i = 0; i < residual.size(); ++i) {
            r[i] = residual[i];
            if (!std::isfinite(r[i]) || !std::isfinite(J[2 * i]) || !std::isfinite(J[2 * i + 1])) return false;
        }
        return true;
    }
    // (F0, a) at (p, α).
    std::array<double, 2> linear(const double* z) { return columns_.solve(z[0], z[1]).c; }

private:
    CompensationColumns columns_;
};

struct CompensationCandidate {
    double cost, F0, power, a, alpha;
};

// Every α of a log-spaced grid over [alpha_lo, alpha_hi] (steps + 1 values) for each power p, (F0, a) solved exactly
// inside their bounds; sorted by cost (½ Σ residual²), best first.
inline std::vector<CompensationCandidate> compensation_candidates(const ChannelTarget& t,
                                                                  const std::vector<double>& powers, double alpha_lo,
                                                                  double alpha_hi, int steps, double F0_lo,
                                                                  double F0_hi, double a_lo, double a_hi) {
    CompensationColumns columns(t, {F0_lo, F0_hi}, {a_lo, a_hi});
    std::vector<CompensationCandidate> candidates;
    for (double power : powers)
        for (int j = 0; j <= steps; ++j) {
            const double alpha = alpha_lo * std::pow(alpha_hi / alpha_lo, double(j) / steps);
            const TwoColumnSolution s = columns.solve(power, alpha);
            double cost = 0.0;
            for (double r : columns.r()) cost += 0.5 * r * r;
            if (std::isfinite(cost)) candidates.push_back({cost, s.c[0], power, s.c[1], alpha});
        }
    std::stable_sort(candidates.begin(), candidates.end(),
                     [](const CompensationCandidate& x, const CompensationCandidate& y) { return x.cost < y.cost; });
    return candidates;
}

}  // namespace metalfit::detail
