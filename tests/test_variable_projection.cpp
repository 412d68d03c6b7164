// The pieces of the two-parameter variable projection (schlick-comp-general's (p, α), rational's (c, d)): the bounded
// Levenberg–Marquardt against optima known in closed form, with and without an active bound; the bounded two-column
// linear solve against the box's optimality conditions (KKT); Kaufman's Jacobian against finite differences of the
// projected cost it is the gradient of.
#include <gtest/gtest.h>

#include <array>
#include <cmath>
#include <random>
#include <vector>

#include "libfit/base/bounded_levenberg_marquardt.hpp"
#include "libfit/models/compensation_projection.hpp"
#include "libfit/models/rational/rational.hpp"
#include "libfit/models/two_column_projection.hpp"

namespace metalfit {
namespace test_variable_projection {

// Rosenbrock as least squares: r = (10 (y − x²), 1 − x), minimum 0 at (1, 1).
bool rosenbrock(const double* z, double* r, double* J) {
    r[0] = 10 * (z[1] - z[0] * z[0]);
    r[1] = 1 - z[0];
    J[0] = -20 * z[0], J[1] = 10;
    J[2] = -1, J[3] = 0;
    return true;
}
const auto kKeepGoing = [](int, double, const std::array<double, 2>&) { return true; };

TEST(BoundedLevenbergMarquardt, FindsRosenbrocksMinimumFromTheTextbookStart) {
    const auto result = bounded_levenberg_marquardt<2>(rosenbrock, 2, {-1.2, 1.0}, {-10, -10}, {10, 10}, kKeepGoing);
    EXPECT_TRUE(result.converged);
    EXPECT_NEAR(result.x[0], 1.0, 1e-9);
    EXPECT_NEAR(result.x[1], 1.0, 1e-9);
    EXPECT_LT(result.cost, 1e-20);
    EXPECT_DOUBLE_EQ(result.initial_cost, 0.5 * (100 * 0.44 * 0.44 + 2.2 * 2.2));
}

// With x ≤ 0.5 the minimum of (1 − x)² + 100 (y − x²)² is at x = 0.5, y = x² = 0.25 (y follows x², then (1 − x)²
// decreases up to the bound).
TEST(BoundedLevenbergMarquardt, HoldsTheConstrainedOptimumOnABound) {
    for (const std::array<double, 2> start : {std::array<double, 2>{-1.2, 1.0}, {0.4, -3.0}, {0.5, 0.25}}) {
        const auto result = bounded_levenberg_marquardt<2>(rosenbrock, 2, start, {-10, -10}, {0.5, 10}, kKeepGoing);
        EXPECT_TRUE(result.converged);
        EXPECT_EQ(result.x[0], 0.5);
        EXPECT_NEAR(result.x[1], 0.25, 1e-9);
        EXPECT_NEAR(result.cost, 0.5 * 0.25, 1e-12);
    }
}

TEST(BoundedLevenbergMarquardt, AStartOutsideTheBoxIsClampedAndAnUnevaluablePointRejected) {
    // Evaluable only for y ≤ 2: the path from (−1.2, 1) must stay below it; the minimum (1, 1) is inside.
    int refused = 0;
    const auto limited = [&refused](const double* z, double* r, double* J) {
        if (z[1] > 2.0) return ++refused, false;
        return rosenbrock(z, r, J);
    };
    const auto result = bounded_levenberg_marquardt<2>(limited, 2, {-30.0, 1.0}, {-1.2, -10}, {10, 10}, kKeepGoing);
    EXPECT_TRUE(result.converged);
    EXPECT_NEAR(result.x[0], 1.0, 1e-9);
    EXPECT_NEAR(result.x[1], 1.0, 1e-9);
}

TEST(BoundedLevenbergMarquardt, KeepGoingAbandonsTheSolve) {
    int asked = 0;
    const auto result = bounded_levenberg_marquardt<2>(rosenbrock, 2, {-1.2, 1.0}, {-10, -10}, {10, 10},
                                                       [&asked](int iteration, double, const std::array<double, 2>&) {
                                                           ++asked;
                                                           return iteration < 3;
                                                       });
    EXPECT_TRUE(result.abandoned);
    EXPECT_FALSE(result.converged);
    EXPECT_GE(result.iterations, 3);
    EXPECT_GE(asked, 1);
}

// The box optimum of a convex quadratic satisfies KKT: each coefficient strictly inside has a zero gradient
// component x_j · r; one on its lower bound a gradient ≥ 0, on its upper bound ≤ 0.
TEST(TwoColumnFit, MeetsTheBoxOptimalityConditions) {
    std::mt19937 random(20261204);
    std::uniform_real_distribution<double> u(-1.0, 1.0);
    int interior = 0, on_a_bound = 0;
    for (int trial = 0; trial < 2000; ++trial) {
        const std::size_t n = 40;
        std::vector<double> x1(n), x2(n), y(n), r(n);
        const double tilt = u(random);  // near-collinear columns sometimes
        for (std::size_t i = 0; i < n; ++i) {
            x1[i] = u(random);
            x2[i] = tilt * x1[i] + (trial % 3 == 0 ? 1e-4 : 1.0) * u(random);
            y[i] = 3 * u(random);
        }
        const std::array<double, 2> lower{-1.0 - u(random) * 0.5, -2.0}, upper{1.0, 0.5 + u(random) * 0.4};
        const detail::TwoColumnSolution s = detail::two_column_fit(x1, x2, y, lower, upper, r.data());
        double g[2] = {0, 0}, scale = 0;
        for (std::size_t i = 0; i < n; ++i) {
            EXPECT_NEAR(r[i], s.c[0] * x1[i] + s.c[1] * x2[i] - y[i], 1e-12);
            g[0] += x1[i] * r[i], g[1] += x2[i] * r[i];
            scale += std::abs(y[i]) * (std::abs(x1[i]) + std::abs(x2[i]));
        }
        for (int j = 0; j < 2; ++j) {
            ASSERT_GE(s.c[j], lower[j]);
            ASSERT_LE(s.c[j], upper[j]);
            const double tolerance = 1e-9 * scale;
            if (s.c[j] > lower[j] && s.c[j] < upper[j]) {
                EXPECT_TRUE(s.free[j]);
                EXPECT_NEAR(g[j], 0.0, tolerance) << trial << " " << j;
                ++interior;
            } else {
                EXPECT_FALSE(s.free[j]);
                if (s.c[j] == lower[j]) {
                    EXPECT_GE(g[j], -tolerance) << trial << " " << j;
                }
                if (s.c[j] == upper[j]) {
                    EXPECT_LE(g[j], tolerance) << trial << " " << j;
                }
                ++on_a_bound;
            }
        }
    }
    EXPECT_GT(interior, 500);  // both cases exercised
    EXPECT_GT(on_a_bound, 500);
}

// A target like the fits': Gauss–Legendre-like interior nodes, a metal-like curve, relative weights.
ChannelTarget metal_like_target(double F0, double dip) {
    ChannelTarget t;
    const int n = 64;
    for (int i = 0; i < n; ++i) {
        const double mu = (i + 0.5) / n, m = 1 - mu;
        const double R = F0 + (1 - F0) * std::pow(m, 5.0) - dip * mu * std::pow(m, 3.0);
        t.mu.push_back(mu);
        t.value.push_back(R);
        t.scale.push_back(std::sqrt(1.0 / n) / R);
    }
    return t;
}

// ½ Σ r² of a projection at z, and its gradient by central differences.
template <class P>
double projected_cost(P& projection, std::array<double, 2> z) {
    std::vector<double> r(projection.residuals()), J(2 * projection.residuals());
    if (!projection(z.data(), r.data(), J.data())) return NAN;
    double cost = 0;
    for (double e : r) cost += 0.5 * e * e;
    return cost;
}

template <class P>
void expect_kaufman_gradient(P& projection, std::array<double, 2> z, const char* what) {
    std::vector<double> r(projection.residuals()), J(2 * projection.residuals());
    ASSERT_TRUE(projection(z.data(), r.data(), J.data())) << what;
    for (int j = 0; j < 2; ++j) {
        double g = 0;
        for (std::size_t i = 0; i < r.size(); ++i) g += J[2 * i + j] * r[i];
        const double h = 1e-6 * std::max(1.0, std::abs(z[j]));
        auto up = z, down = z;
        up[j] += h, down[j] -= h;
        const double numeric = (projected_cost(projection, up) - projected_cost(projection, down)) / (2 * h);
        EXPECT_NEAR(g, numeric, 1e-6 * std::abs(numeric) + 1e-12)
            << what << " z = (" << z[0] << ", " << z[1] << ") parameter " << j;
    }
}

TEST(VariableProjection, KaufmansGradientIsTheProjectedCostsDerivative) {
    const ChannelTarget gold_like = metal_like_target(0.9, 0.4), dark = metal_like_target(0.05, -0.3);
    for (const ChannelTarget* t : {&gold_like, &dark}) {
        detail::CompensationSurface surface(*t, {-1.0, 2.0}, {-20.0, 20.0});
        for (const std::array<double, 2> z : {std::array<double, 2>{5.0, 6.0}, {2.5, 0.7}, {12.0, 30.0}, {7.4, 6.6}})
            expect_kaufman_gradient(surface, z, "schlick-comp-general");
        // With a tight box on a the linear solve sits on a bound: the projection keeps only the free column.
        detail::CompensationSurface tight(*t, {-1.0, 2.0}, {-0.01, 0.01});
        expect_kaufman_gradient(tight, {5.0, 3.0}, "schlick-comp-general, a on its bound");
        models::Rational::Projection rational(*t);
        for (const std::array<double, 2> z : {std::array<double, 2>{0.0, 0.0}, {3.0, 3.0}, {30.0, 300.0}, {-0.5, 0.2}})
            expect_kaufman_gradient(rational, z, "rational");
    }
}

TEST(VariableProjection, RationalRefusesADenominatorWithoutSignAtTheNodes) {
    const ChannelTarget t = metal_like_target(0.6, 0.1);
    models::Rational::Projection rational(t);
    std::vector<double> r(rational.residuals()), J(2 * rational.residuals());
    const std::array<double, 2> pole{-3.0, 0.0};  // 1 − 3 μ: zero at μ = 1/3
    EXPECT_FALSE(rational(pole.data(), r.data(), J.data()));
    const std::array<double, 2> fine{-0.9, 0.0};
    EXPECT_TRUE(rational(fine.data(), r.data(), J.data()));
}

}  // namespace test_variable_projection
}  // namespace metalfit
