// Gauss–Legendre convergence figures (bench/convergence.hpp).
#include <gtest/gtest.h>

#include <cmath>

#include "metalfit_bench/convergence.hpp"

namespace test_bench_convergence {

using namespace metalfit::bench;

TEST(Convergence, ChangesDecreaseWithNForASmoothIntegrand) {
    const auto f = [](double mu) { return std::exp(mu); };
    const std::vector<int> nodes{1, 2, 3, 4, 5};
    const Convergence c = gauss_legendre_convergence(f, nodes, 64);
    EXPECT_NEAR(c.reference_estimate, std::exp(1.0) - 1.0, 1e-14);
    ASSERT_EQ(c.points.size(), nodes.size());
    EXPECT_TRUE(std::isnan(c.points[0].change));
    for (std::size_t i = 1; i < c.points.size(); ++i) {
        EXPECT_LT(c.points[i].to_reference, c.points[i - 1].to_reference) << c.points[i].nodes << " nodes";
        if (i >= 2) {
            EXPECT_LT(c.points[i].change, c.points[i - 1].change) << c.points[i].nodes << " nodes";
        }
        EXPECT_GE(c.points[i].seconds, 0.0);
    }
    EXPECT_GT(c.points[0].to_reference, 1e-2);  // one node: the midpoint rule, error e − 1 − e^½ ≈ 0.07
    EXPECT_LT(c.points[4].to_reference, 1e-10);
}

TEST(Convergence, TheIssueNodeCountsConvergeOnARungeFunction) {
    // 1 / (1 + 25 (2μ − 1)²): analytic but with poles near [0, 1], so the error falls slowly over 8 … 512 nodes.
    const auto f = [](double mu) { return 1.0 / (1.0 + 25.0 * (2 * mu - 1) * (2 * mu - 1)); };
    const std::vector<int> counts = convergence_node_counts();
    ASSERT_EQ(counts, (std::vector<int>{8, 16, 32, 64, 128, 256, 512}));
    const Convergence c = gauss_legendre_convergence(f, counts, 2048);
    EXPECT_NEAR(c.reference_estimate, std::atan(5.0) / 5.0, 1e-14);
    for (std::size_t i = 1; i < c.points.size(); ++i)
        if (c.points[i - 1].to_reference > 1e-13) {
            EXPECT_LT(c.points[i].to_reference, c.points[i - 1].to_reference) << c.points[i].nodes;
        }
    EXPECT_GT(c.points[0].to_reference, 1e-4);
    EXPECT_LT(c.points.back().to_reference, 1e-13);
}

}  // namespace test_bench_convergence
