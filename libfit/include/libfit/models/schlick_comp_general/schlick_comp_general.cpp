#include "libfit/models/schlick_comp_general/schlick_comp_general.hpp"

#include <algorithm>
#include <cmath>
#include <cstddef>
#include <limits>
#include <utility>

#include "libfit/models/compensation_projection.hpp"

namespace metalfit::models {

std::vector<ClosedForm> SchlickCompGeneral::closed_forms(const ClosedFormInput& input) {
    const RGB F0 = input.reference(1.0);
    ClosedForm form{"r1", "F0 = R(1), p = 5, a = 0 (Schlick)", {}};
    for (int c = 0; c < 3; ++c) form.channel[c].params = ChannelParameters{F0[c], 5.0, 0.0, 6.0};
    return {form};
}

std::vector<ChannelParameters> SchlickCompGeneral::target_starts(const ChannelTarget& t) {
    const auto& F0 = kParameters[0];
    const auto& a = kParameters[2];
    const auto& alpha = kParameters[3];
    const std::vector<double> powers{1.5, 2.0,  2.5,  3.0,  3.5,  4.0,  5.0,  6.0,  7.0,
                                     8.0, 10.0, 12.0, 16.0, 20.0, 24.0, 32.0, 48.0, 64.0};
    constexpr int kAlphaSteps = 32;
    const std::size_t n = t.mu.size(), P = powers.size(), A = kAlphaSteps + 1;
    // mᵖ and m^α at the nodes for every power and α of the grids, each computed once (exp(e ln m)).
    std::vector<double> log_m(n), scaled_mu(n), alphas(A), m_alpha(A * n), x1(n), x2(n), y(n), r(n);
    for (std::size_t i = 0; i < n; ++i) {
        const double mu = model_math::clamp_mu(t.mu[i]);
        log_m[i] = std::log(1.0 - mu);
        scaled_mu[i] = t.scale[i] * mu;
    }
    const auto power_of_m = [&log_m](std::size_t i, double e) {
        return std::isinf(log_m[i]) ? 0.0 : std::exp(e * log_m[i]);
    };
    for (std::size_t j = 0; j < A; ++j) {
        alphas[j] = alpha.lower * std::pow(alpha.upper / alpha.lower, double(j) / kAlphaSteps);
        for (std::size_t i = 0; i < n; ++i) m_alpha[j * n + i] = power_of_m(i, alphas[j]);
    }
    // (F0, a) solved exactly at every (p, α) of the grid; the grid's local minima (no lower neighbour among the
    // eight) are the valleys of the (p, α) surface (copper green of Babar: p ≈ 6, α ≈ 16 beside p ≈ 7.4, α ≈ 6.6),
    // each a start, lowest first.
    std::vector<detail::CompensationCandidate> grid(P * A);
    // Where the data need almost no compensation the α of a valley is arbitrary and can lead LM into another one
    // (vanadium nitride red of Pflüger: 0.0027 at p = 16.9, a = −3.5 instead of 0.0022 at p = 9.7, a = 0.02): the
    // best powers of the uncompensated curve F0 + (1 − F0) mᵖ (a = 0, α = 1) start as well.
    std::vector<std::pair<double, ChannelParameters>> uncompensated;  // (½ Σ residual², start)
    for (std::size_t k = 0; k < P; ++k) {
        double x1y = 0, x1x1 = 0;
        for (std::size_t i = 0; i < n; ++i) {
            const double w = power_of_m(i, powers[k]);
            x1[i] = t.scale[i] * (1.0 - w);
            y[i] = t.scale[i] * (t.value[i] - w);
            x1y += x1[i] * y[i], x1x1 += x1[i] * x1[i];
        }
        for (std::size_t j = 0; j < A; ++j) {
            for (std::size_t i = 0; i < n; ++i) x2[i] = -scaled_mu[i] * m_alpha[j * n + i];
            const detail::TwoColumnSolution s =
                detail::two_column_fit(x1, x2, y, {F0.lower, a.lower}, {F0.upper, a.upper}, r.data());
            double cost = 0;
            for (double e : r) cost += 0.5 * e * e;
            grid[k * A + j] = {std::isfinite(cost) ? cost : std::numeric_limits<double>::infinity(), s.c[0], powers[k],
                               s.c[1], alphas[j]};
        }
        if (!(x1x1 > 0.0)) continue;
        const double f0 = std::clamp(x1y / x1x1, F0.lower, F0.upper);
        double cost = 0.0;
        for (std::size_t i = 0; i < n; ++i) {
            const double e = x1[i] * f0 - y[i];
            cost += 0.5 * e * e;
        }
        uncompensated.push_back({cost, ChannelParameters{f0, powers[k], 0.0, 1.0}});
    }
    std::vector<detail::CompensationCandidate> minima;
    for (std::size_t k = 0; k < P; ++k)
        for (std::size_t j = 0; j < A; ++j) {
            const double c = grid[k * A + j].cost;
            if (!std::isfinite(c)) continue;
            bool lowest = true;
            for (int dk = -1; dk <= 1 && lowest; ++dk)
                for (int dj = -1; dj <= 1 && lowest; ++dj) {
                    const std::ptrdiff_t kk = std::ptrdiff_t(k) + dk, jj = std::ptrdiff_t(j) + dj;
                    if ((dk == 0 && dj == 0) || kk < 0 || jj < 0 || kk >= std::ptrdiff_t(P) || jj >= std::ptrdiff_t(A))
                        continue;
                    const double neighbour = grid[std::size_t(kk) * A + std::size_t(jj)].cost;
                    // Ties (a flat run of the grid) count once: the first in the grid's order.
                    if (neighbour < c || (neighbour == c && (kk < std::ptrdiff_t(k) ||
                                                             (kk == std::ptrdiff_t(k) && jj < std::ptrdiff_t(j)))))
                        lowest = false;
                }
            if (lowest) minima.push_back(grid[k * A + j]);
        }
    std::stable_sort(
        minima.begin(), minima.end(),
        [](const detail::CompensationCandidate& x, const detail::CompensationCandidate& y) { return x.cost < y.cost; });
    std::vector<ChannelParameters> starts;
    for (const auto& c : minima) starts.push_back({c.F0, c.power, c.a, c.alpha});
    std::stable_sort(uncompensated.begin(), uncompensated.end(),
                     [](const auto& x, const auto& y) { return x.first < y.first; });
    for (std::size_t i = 0; i < uncompensated.size() && i < 3; ++i) starts.push_back(uncompensated[i].second);
    return starts;
}

}  // namespace metalfit::models
