// Gauss–Legendre on [0, 1]: known small rules, exactness up to degree 2n − 1 (and not beyond),
// agreement with an extended-precision reference, and convergence on smooth and rough integrands.
#include <gtest/gtest.h>

#include <cmath>
#include <functional>
#include <limits>
#include <numbers>
#include <stdexcept>
#include <vector>

#include "libfit/base/quadrature.hpp"

namespace metalfit {
namespace test_quadrature {

double integrate(const std::vector<QuadratureNode>& rule, const std::function<double(double)>& f) {
    double sum = 0.0;
    for (const auto& node : rule) sum += node.weight * f(node.mu);
    return sum;
}

double integrate(int n, const std::function<double(double)>& f) { return integrate(gauss_legendre_unit(n), f); }

// Exact GL error on [0, 1] for f = x^{2n}: (n!)⁴ / ((2n + 1) ((2n)!)²) (the rule underestimates).
double error_at_degree_2n(int n) {
    double ratio = 1.0;  // (n!)² / (2n)!
    for (int k = 1; k <= n; ++k) ratio *= static_cast<double>(k) / (n + k);
    return ratio * ratio / (2 * n + 1);
}

TEST(Quadrature, RejectsInvalidNodeCounts) {
    for (int n : {0, -1, -1000, 4097, 10000}) EXPECT_THROW(gauss_legendre_unit(n), std::invalid_argument) << n;
    EXPECT_NO_THROW(gauss_legendre_unit(1));
    EXPECT_NO_THROW(gauss_legendre_unit(4096));
}

TEST(Quadrature, OneNodeIsTheMidpoint) {
    const auto rule = gauss_legendre_unit(1);
    ASSERT_EQ(rule.size(), 1u);
    EXPECT_DOUBLE_EQ(rule[0].mu, 0.5);
    EXPECT_DOUBLE_EQ(rule[0].weight, 1.0);
}

TEST(Quadrature, TwoNodesAreKnown) {
    const auto rule = gauss_legendre_unit(2);
    ASSERT_EQ(rule.size(), 2u);
    const double h = 1.0 / (2.0 * std::sqrt(3.0));
    EXPECT_NEAR(rule[0].mu, 0.5 - h, 4e-16);
    EXPECT_NEAR(rule[1].mu, 0.5 + h, 4e-16);
    EXPECT_NEAR(rule[0].weight, 0.5, 4e-16);
    EXPECT_NEAR(rule[1].weight, 0.5, 4e-16);
}

TEST(Quadrature, ThreeNodesAreKnown) {
    const auto rule = gauss_legendre_unit(3);
    ASSERT_EQ(rule.size(), 3u);
    const double h = std::sqrt(3.0 / 5.0) / 2.0;
    EXPECT_NEAR(rule[0].mu, 0.5 - h, 4e-16);
    EXPECT_NEAR(rule[1].mu, 0.5, 4e-16);
    EXPECT_NEAR(rule[2].mu, 0.5 + h, 4e-16);
    EXPECT_NEAR(rule[0].weight, 5.0 / 18.0, 4e-16);
    EXPECT_NEAR(rule[1].weight, 4.0 / 9.0, 4e-16);
    EXPECT_NEAR(rule[2].weight, 5.0 / 18.0, 4e-16);
}

TEST(Quadrature, NodesAscendInsideTheUnitIntervalWithPositiveWeights) {
    for (int n : {1, 2, 3, 4, 5, 8, 17, 64, 128, 1000, 1024, 4096}) {
        const auto rule = gauss_legendre_unit(n);
        ASSERT_EQ(rule.size(), static_cast<std::size_t>(n));
        for (std::size_t i = 0; i < rule.size(); ++i) {
            EXPECT_GT(rule[i].mu, 0.0) << "n=" << n << " i=" << i;
            EXPECT_LT(rule[i].mu, 1.0) << "n=" << n << " i=" << i;
            EXPECT_GT(rule[i].weight, 0.0) << "n=" << n << " i=" << i;
            if (i > 0) {
                EXPECT_GT(rule[i].mu, rule[i - 1].mu) << "n=" << n << " i=" << i;
            }
        }
    }
}

TEST(Quadrature, WeightsSumToOne) {
    for (int n : {1, 2, 3, 4, 5, 8, 17, 64, 128, 1000, 1024, 4096}) {
        double sum = 0.0;
        for (const auto& node : gauss_legendre_unit(n)) sum += node.weight;
        EXPECT_NEAR(sum, 1.0, 1e-14) << "n=" << n;
    }
}

TEST(Quadrature, RuleIsMirrorSymmetric) {
    for (int n : {1, 2, 3, 4, 7, 8, 64, 127, 1024, 4095}) {
        const auto rule = gauss_legendre_unit(n);
        for (int i = 0; i < n; ++i) {
            const auto& lo = rule[static_cast<std::size_t>(i)];
            const auto& hi = rule[static_cast<std::size_t>(n - 1 - i)];
            EXPECT_NEAR(lo.mu + hi.mu, 1.0, 1e-15) << "n=" << n << " i=" << i;
            EXPECT_EQ(lo.weight, hi.weight) << "n=" << n << " i=" << i;
        }
        if (n % 2 == 1) {
            EXPECT_EQ(rule[static_cast<std::size_t>(n / 2)].mu, 0.5) << "n=" << n;
        }
    }
}

TEST(Quadrature, ExactForMonomialsUpToDegreeTwoNMinusOne) {
    for (int n : {1, 2, 3, 8, 128}) {
        const auto rule = gauss_legendre_unit(n);
        for (int d = 0; d <= 2 * n - 1; ++d) {
            const double exact = 1.0 / (d + 1);
            const double got = integrate(rule, [d](double x) { return std::pow(x, d); });
            EXPECT_NEAR(got, exact, 1e-13 * exact) << "n=" << n << " degree=" << d;
        }
    }
}

TEST(Quadrature, DegreeBoundIsTight) {
    // x^{2n} is the first monomial the rule misses, by exactly the textbook error term.
    for (int n : {1, 2, 3, 4, 8}) {
        const double exact = 1.0 / (2 * n + 1);
        const double got = integrate(n, [n](double x) { return std::pow(x, 2 * n); });
        const double expected_error = error_at_degree_2n(n);
        EXPECT_GT(exact - got, 1e3 * 1e-13 * exact) << "n=" << n;  // far beyond rounding
        EXPECT_NEAR(exact - got, expected_error, 1e-6 * expected_error) << "n=" << n;
    }
    EXPECT_NEAR(error_at_degree_2n(1), 1.0 / 12.0, 1e-17);  // ∫x² = 1/3 vs the midpoint's 1/4
}

// Newton on the same recurrence in long double: an independent, more precise reference.
std::vector<long double> reference_nodes(int n) {
    std::vector<long double> mu(static_cast<std::size_t>(n));
    for (int i = 1; i <= n; ++i) {
        long double x = std::cos(std::numbers::pi_v<long double> * (i - 0.25L) / (n + 0.5L));
        for (int iter = 0; iter < 100; ++iter) {
            long double p0 = 1.0L, p1 = x;
            for (int k = 1; k < n; ++k) {
                const long double p2 = ((2 * k + 1) * x * p1 - k * p0) / (k + 1);
                p0 = p1;
                p1 = p2;
            }
            const long double dp = n * (x * p1 - p0) / (x * x - 1.0L);
            const long double step = p1 / dp;
            x -= step;
            if (std::abs(step) <= 4 * std::numeric_limits<long double>::epsilon()) break;
        }
        mu[static_cast<std::size_t>(i - 1)] = (1.0L - x) / 2.0L;
    }
    return mu;
}

TEST(Quadrature, NodesMatchExtendedPrecisionReference) {
    if (std::numeric_limits<long double>::digits <= std::numeric_limits<double>::digits)
        GTEST_SKIP() << "long double is no wider than double here";
    for (int n : {5, 64, 257, 1024}) {
        const auto rule = gauss_legendre_unit(n);
        const auto ref = reference_nodes(n);
        for (int i = 0; i < n; ++i) {
            const auto idx = static_cast<std::size_t>(i);
            EXPECT_NEAR(rule[idx].mu, static_cast<double>(ref[idx]), 1e-15) << "n=" << n << " i=" << i;
        }
        // The node nearest 0 (≈ 1.4e-6 for n = 1024) keeps its relative accuracy too.
        EXPECT_NEAR(rule[0].mu, static_cast<double>(ref[0]), 1e-12 * static_cast<double>(ref[0])) << "n=" << n;
    }
}

TEST(Quadrature, SmoothIntegrandConvergesGeometrically) {
    const double exact = std::numbers::e - 1.0;
    double previous = INFINITY;
    for (int n = 1; n <= 6; ++n) {
        const double error = std::abs(integrate(n, [](double x) { return std::exp(x); }) - exact);
        EXPECT_LT(error, 1e-2 * previous) << "n=" << n;  // each node gains over two digits
        previous = error;
    }
    EXPECT_GT(std::abs(integrate(2, [](double x) { return std::exp(x); }) - exact), 1e-4);
    for (int n : {8, 16, 64, 1024})
        EXPECT_NEAR(integrate(n, [](double x) { return std::exp(x); }), exact, 4e-15) << "n=" << n;
}

TEST(Quadrature, RungeIntegrandConvergesGeometricallyButSlower) {
    // Poles at ±i/5 limit the rate; still geometric.
    const double exact = std::atan(5.0) / 5.0;
    auto f = [](double x) { return 1.0 / (1.0 + 25.0 * x * x); };
    double previous = INFINITY;
    for (int n = 4; n <= 64; n += 4) {
        const double error = std::abs(integrate(n, f) - exact);
        if (previous > 1e-14) {
            EXPECT_LT(error, 0.5 * previous) << "n=" << n;
        }
        previous = error;
    }
    EXPECT_GT(std::abs(integrate(4, f) - exact), 1e-4);
    EXPECT_NEAR(integrate(64, f), exact, 1e-14);
}

TEST(Quadrature, SqrtConvergesAlgebraically) {
    // The √x endpoint singularity caps the rate at O(n⁻³): doubling n gains a factor ≈ 8, not digits.
    const double exact = 2.0 / 3.0;
    auto f = [](double x) { return std::sqrt(x); };
    double previous = INFINITY;
    for (int n = 4; n <= 512; n *= 2) {
        const double error = std::abs(integrate(n, f) - exact);
        if (n >= 8) {
            EXPECT_GT(previous / error, 6.0) << "n=" << n;
            EXPECT_LT(previous / error, 10.0) << "n=" << n;
        }
        previous = error;
    }
    EXPECT_GT(previous, 1e-11);  // n = 512 is still far from machine precision
    EXPECT_LT(previous, 1e-7);
}

}  // namespace test_quadrature
}  // namespace metalfit
