// Variable projection with two linear parameters (models that are linear in two of their parameters for fixed
// others: the compensated Schlick families, rational): the bounded linear solve and Kaufman's projection of the
// Jacobian of the non-linear ones (Linda Kaufman, "A variable projection method for solving separable nonlinear
// least squares problems", BIT 15, 1975).
#pragma once

#include <algorithm>
#include <array>
#include <cmath>
#include <cstddef>
#include <initializer_list>
#include <limits>
#include <vector>

namespace metalfit::detail {

// min ‖c₁ x₁ + c₂ x₂ − y‖ over c ∈ [lower, upper] (a box), by the QR factorisation of [x₁ x₂] (Gram–Schmidt on two
// columns: the columns 1 − mᵖ and μ m^α can be close to collinear, so no normal equations); where the unconstrained
// solution leaves the box, the best of the four edges (each a one-column problem, clamped), which is the box's
// optimum for a convex quadratic. Residuals r = c₁ x₁ + c₂ x₂ − y are written.
struct TwoColumnSolution {
    std::array<double, 2> c{};
    std::array<bool, 2> free{};  // strictly inside its bounds: a column of the projection
};

inline TwoColumnSolution two_column_fit(const std::vector<double>& x1, const std::vector<double>& x2,
                                        const std::vector<double>& y, const std::array<double, 2>& lower,
                                        const std::array<double, 2>& upper, double* r) {
    const std::size_t n = y.size();
    const auto residuals_cost = [&](double c1, double c2) {
        double cost = 0;
        for (std::size_t i = 0; i < n; ++i) {
            r[i] = c1 * x1[i] + c2 * x2[i] - y[i];
            cost += r[i] * r[i];
        }
        return cost;
    };
    double n1 = 0, d12 = 0, d1y = 0;
    for (std::size_t i = 0; i < n; ++i) n1 += x1[i] * x1[i], d12 += x1[i] * x2[i], d1y += x1[i] * y[i];
    TwoColumnSolution s;
    if (n1 > 0) {
        // q₁ = x₁ / ‖x₁‖, x₂' = x₂ − (q₁·x₂) q₁: R = [[‖x₁‖, q₁·x₂], [0, ‖x₂'‖]].
        const double r11 = std::sqrt(n1), r12 = d12 / r11, q1y = d1y / r11;
        double n2 = 0, q2y = 0;
        for (std::size_t i = 0; i < n; ++i) {
            const double v = x2[i] - r12 * x1[i] / r11;
            n2 += v * v, q2y += v * y[i];
        }
        const double r22 = std::sqrt(n2);
        if (r22 > 1e-13 * std::max(r11, std::abs(r12))) {
            const double c2 = q2y / n2, c1 = (q1y - r12 * c2) / r11;
            if (c1 >= lower[0] && c1 <= upper[0] && c2 >= lower[1] && c2 <= upper[1]) {
                s.c = {c1, c2};
                s.free = {c1 > lower[0] && c1<upper[0], c2> lower[1] && c2 < upper[1]};
                residuals_cost(c1, c2);
                return s;
            }
        }
    }
    // The edges: one coefficient on a bound, the other solved and clamped.
    const auto solve_one = [&](const std::vector<double>& x, const std::vector<double>& other, double c_other,
                               double lo, double hi) {
        double xx = 0, xy = 0;
        for (std::size_t i = 0; i < n; ++i) xx += x[i] * x[i], xy += x[i] * (y[i] - c_other * other[i]);
        return std::clamp(xx > 0 ? xy / xx : 0.0, lo, hi);
    };
    double best = std::numeric_limits<double>::infinity();
    std::array<double, 2> c_best{};
    for (int k = 0; k < 4; ++k) {
        std::array<double, 2> c;
        if (k < 2) {
            c[0] = k == 0 ? lower[0] : upper[0];
            c[1] = solve_one(x2, x1, c[0], lower[1], upper[1]);
        } else {
            c[1] = k == 2 ? lower[1] : upper[1];
            c[0] = solve_one(x1, x2, c[1], lower[0], upper[0]);
        }
        const double cost = residuals_cost(c[0], c[1]);
        if (cost < best) best = cost, c_best = c;
    }
    s.c = c_best;
    s.free = {c_best[0] > lower[0] && c_best[0]<upper[0], c_best[1]> lower[1] && c_best[1] < upper[1]};
    residuals_cost(c_best[0], c_best[1]);
    return s;
}

// The Jacobian columns (at stride `stride`; a negative column is skipped) made orthogonal to the free columns
// among x₁, x₂ (Gram–Schmidt): Kaufman's variable-projection Jacobian, whose Jᵀ r is the projected cost's exact
// gradient (r is orthogonal to the free columns at the linear solution, and a column on its bound is held).
inline void project_out_free_columns(const std::vector<double>& x1, const std::vector<double>& x2,
                                     const std::array<bool, 2>& free_columns, std::initializer_list<int> columns,
                                     int stride, double* J) {
    const std::size_t n = x1.size();
    // The orthonormal basis in two scratch columns kept by the thread, not allocated at every evaluation of the
    // projected residuals (callgrind of `fit --all --model schlick-comp-general,rational -j1 --json`: 2.023 G →
    // 2.006 G instructions, the records identical).
    thread_local std::array<std::vector<double>, 2> basis;
    std::size_t count = 0;
    for (std::size_t which = 0; which < 2; ++which) {
        if (!free_columns[which]) continue;
        const std::vector<double>& x = which == 0 ? x1 : x2;
        std::vector<double>& v = basis[count];
        v.assign(x.begin(), x.end());
        for (std::size_t k = 0; k < count; ++k) {
            const std::vector<double>& b = basis[k];
            double d = 0;
            for (std::size_t i = 0; i < n; ++i) d += b[i] * v[i];
            for (std::size_t i = 0; i < n; ++i) v[i] -= d * b[i];
        }
        double norm = 0;
        for (double e : v) norm += e * e;
        norm = std::sqrt(norm);
        if (!(norm > 0)) continue;
        for (double& e : v) e /= norm;
        ++count;
    }
    for (int column : columns) {
        if (column < 0) continue;
        for (std::size_t k = 0; k < count; ++k) {
            const std::vector<double>& b = basis[k];
            double d = 0;
            for (std::size_t i = 0; i < n; ++i) d += b[i] * J[i * stride + column];
            for (std::size_t i = 0; i < n; ++i) J[i * stride + column] -= d * b[i];
        }
    }
}

}  // namespace metalfit::detail
