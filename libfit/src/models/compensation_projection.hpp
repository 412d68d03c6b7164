// Variable projection for the compensated Schlick families F0 + (1 − F0) mᵖ − a μ m^α (internal): for fixed p and α
// the curve is linear in (F0, a), solved exactly; a grid over α (and p) ranks the candidates, the best few become
// starts of the Ceres fit.
#pragma once

#include <algorithm>
#include <cmath>
#include <vector>

#include "libfit/models/model.hpp"
#include "models/linear_least_squares.hpp"

namespace metalfit::detail {

struct CompensationCandidate {
    double cost, F0, power, a, alpha;
};

// Every α of a log-spaced grid over [alpha_lo, alpha_hi] (steps + 1 values) for each power p, solved exactly in
// (F0, a) and clamped into [F0_lo, F0_hi] × [a_lo, a_hi]; sorted by cost (½ Σ residual²), best first.
inline std::vector<CompensationCandidate> compensation_candidates(const ChannelTarget& t,
                                                                  const std::vector<double>& powers, double alpha_lo,
                                                                  double alpha_hi, int steps, double F0_lo,
                                                                  double F0_hi, double a_lo, double a_hi) {
    // m^α at every node for every α of the grid, computed once rather than once per power (the same values).
    const std::size_t n = t.mu.size();
    std::vector<double> alphas, m_alpha;
    for (int j = 0; j <= steps; ++j) {
        const double alpha = alpha_lo * std::pow(alpha_hi / alpha_lo, double(j) / steps);
        alphas.push_back(alpha);
        for (std::size_t i = 0; i < n; ++i) m_alpha.push_back(std::pow(1.0 - t.mu[i], alpha));
    }
    std::vector<CompensationCandidate> candidates;
    std::vector<double> m_power(n);
    for (double power : powers) {
        for (std::size_t i = 0; i < n; ++i) m_power[i] = std::pow(1.0 - t.mu[i], power);
        for (int j = 0; j <= steps; ++j) {
            const double alpha = alphas[j];
            std::vector<std::vector<double>> A(2);
            std::vector<double> y;
            for (std::size_t i = 0; i < n; ++i) {
                const double mu = t.mu[i], w = m_power[i], s = t.scale[i];
                A[0].push_back(s * (1.0 - w));
                A[1].push_back(-s * mu * m_alpha[j * n + i]);
                y.push_back(s * (t.value[i] - w));
            }
            const auto x = linear_least_squares(A, y);
            if (!x) continue;
            const double F0 = std::clamp((*x)[0], F0_lo, F0_hi), a = std::clamp((*x)[1], a_lo, a_hi);
            double cost = 0.0;
            for (std::size_t i = 0; i < y.size(); ++i) {
                const double r = A[0][i] * F0 + A[1][i] * a - y[i];
                cost += 0.5 * r * r;
            }
            candidates.push_back({cost, F0, power, a, alpha});
        }
    }
    std::stable_sort(candidates.begin(), candidates.end(),
                     [](const CompensationCandidate& x, const CompensationCandidate& y) { return x.cost < y.cost; });
    return candidates;
}

}  // namespace metalfit::detail
