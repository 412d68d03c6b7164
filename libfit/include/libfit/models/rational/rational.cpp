#include "libfit/models/rational/rational.hpp"

#include <algorithm>
#include <cmath>

#include "libfit/base/number_text.hpp"
#include "models/linear_least_squares.hpp"

namespace metalfit::models {

std::vector<ChannelParameters> Rational::target_starts(const ChannelTarget& t) {
    constexpr int kIterations = 6;
    std::vector<ChannelParameters> starts;
    std::vector<double> weight(t.mu.size(), 1.0);  // 1 / previous denominator
    for (int it = 0; it < kIterations; ++it) {
        // s w (R (1 + c μ + d μ²) − 1 − a μ − b μ²) = 0 → columns for a, b, c, d and the right-hand side s w (1 − R).
        std::vector<std::vector<double>> A(4);
        std::vector<double> y;
        for (std::size_t i = 0; i < t.mu.size(); ++i) {
            const double mu = t.mu[i], R = t.value[i], s = t.scale[i] * weight[i];
            A[0].push_back(-s * mu);
            A[1].push_back(-s * mu * mu);
            A[2].push_back(s * R * mu);
            A[3].push_back(s * R * mu * mu);
            y.push_back(s * (1.0 - R));
        }
        const auto x = detail::linear_least_squares(std::move(A), std::move(y));
        if (!x) break;
        ChannelParameters p = *x;
        if (!std::all_of(p.begin(), p.end(), [](double v) { return std::isfinite(v); })) break;
        for (std::size_t i = 0; i < t.mu.size(); ++i) {
            const double den = std::abs(1.0 + t.mu[i] * (p[2] + p[3] * t.mu[i]));
            weight[i] = den > 1e-12 ? 1.0 / den : 1.0;
        }
        for (std::size_t i = 0; i < p.size(); ++i) p[i] = std::clamp(p[i], kParameters[i].lower, kParameters[i].upper);
        starts.push_back(std::move(p));
    }
    return starts;
}

std::string Rational::inadmissible(const double* p) {
    if (denominator_minimum(p) > 0) return {};
    return "the denominator 1 + c mu + d mu^2 (c = " + shortest_text(p[2]) + ", d = " + shortest_text(p[3]) +
           ") has a root in [0, 1]: a pole of the curve";
}

}  // namespace metalfit::models
