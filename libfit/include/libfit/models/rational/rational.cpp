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

Rational::Projection::Projection(const ChannelTarget& t) {
    for (std::size_t i = 0; i < t.mu.size(); ++i) {
        mu_.push_back(model_math::clamp_mu(t.mu[i]));
        scale_.push_back(t.scale[i]);
        value_.push_back(t.value[i]);
    }
    const std::size_t n = mu_.size();
    inverse_d_.resize(n), x1_.resize(n), x2_.resize(n), y_.resize(n), r_.resize(n);
}

bool Rational::Projection::solve(const double* z, detail::TwoColumnSolution& solution) {
    const double c = z[0], d = z[1];
    for (std::size_t i = 0; i < mu_.size(); ++i) {
        const double mu = mu_[i], D = 1.0 + mu * (c + d * mu);
        if (!(D > 0.0)) return false;
        inverse_d_[i] = 1.0 / D;
        x1_[i] = scale_[i] * mu * inverse_d_[i];
        x2_[i] = x1_[i] * mu;
        y_[i] = scale_[i] * (value_[i] - inverse_d_[i]);
    }
    solution = detail::two_column_fit(x1_, x2_, y_, {kParameters[0].lower, kParameters[1].lower},
                                      {kParameters[0].upper, kParameters[1].upper}, r_.data());
    return true;
}

bool Rational::Projection::operator()(const double* z, double* r, double* J) {
    detail::TwoColumnSolution s;
    if (!solve(z, s)) return false;
    const double a = s.c[0], b = s.c[1];
    // ∂r/∂c = −s N μ / D², ∂r/∂d = −s N μ² / D² at fixed (a, b), N = 1 + a μ + b μ².
    for (std::size_t i = 0; i < mu_.size(); ++i) {
        const double mu = mu_[i], N = 1.0 + mu * (a + b * mu);
        const double dc = -scale_[i] * N * mu * inverse_d_[i] * inverse_d_[i];
        J[2 * i] = dc, J[2 * i + 1] = dc * mu;
    }
    detail::project_out_free_columns(x1_, x2_, s.free, {0, 1}, 2, J);
    for (std::size_t i = 0; i < mu_.size(); ++i) {
        r[i] = r_[i];
        if (!std::isfinite(r[i]) || !std::isfinite(J[2 * i]) || !std::isfinite(J[2 * i + 1])) return false;
    }
    return true;
}

ChannelParameters Rational::Projection::parameters(const double* z, const ChannelParameters& start) {
    detail::TwoColumnSolution s;
    if (!solve(z, s)) return start;
    return {s.c[0], s.c[1], z[0], z[1]};
}

}  // namespace metalfit::models
