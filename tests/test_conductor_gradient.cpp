// The closed-form gradient of the exact conductor Fresnel (model_math::conductor_fresnel_gradient) and the
// Jacobians conductor-rgb and gulbrandsen build on it (evaluate_with_gradient): checked against Ceres's Jets through
// conductor_fresnel (autodiff of the same formula) on a dense grid of (n, k, μ) with t < 0, k = 0, μ → 0 and μ = 1,
// and against finite differences in long double (a second, independent form).
#include <ceres/jet.h>
#include <gtest/gtest.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <string>
#include <vector>

#include "libfit/models/conductor_rgb/conductor_rgb.hpp"
#include "libfit/models/gulbrandsen/gulbrandsen.hpp"
#include "libfit/models/model_math.hpp"

namespace metalfit {
namespace test_conductor_gradient {

const std::vector<double> kN{1e-3, 0.01, 0.05, 0.2, 0.5, 0.9, 0.999, 1.0, 1.001, 1.1, 1.5, 2.5, 5.0, 20.0, 100.0};
const std::vector<double> kK{0.0, 1e-3, 0.01, 0.1, 0.3, 0.7, 1.0, 2.0, 3.5, 8.0, 30.0, 300.0, 1e4};

// μ on [0, 1] with the ends, μ → 0 and μ → 1.
std::vector<double> mu_grid() {
    std::vector<double> mu{0.0, 1e-12, 1e-8, 1e-6, 1e-4, 1e-3, 1.0 - 1e-9, 1.0};
    for (int i = 1; i < 64; ++i) mu.push_back(i / 64.0);
    return mu;
}

// |a − b| within `relative` of the gradient's scale at that point (its largest component, or the value where all
// vanish): a component that cancels to 0 is compared at the scale of the others, not by its own rounding.
double gradient_scale(const double* g, int count, double value) {
    double s = 0;
    for (int i = 0; i < count; ++i) s = std::max(s, std::abs(g[i]));
    return std::max(s, std::abs(value) * 1e-3);
}

// A model's evaluate_with_gradient against Ceres's Jets through its evaluate (autodiff of the same formula), in long
// double: the derivatives are differences of O(1) terms that are O(μ) as μ → 0, where Jets in double lose
// log10(1/μ) digits, so the 11 extra bits make them the sharper reference. The comparison is at the model's
// parameters, where the two sides t ≥ 0 and t < 0 give one function (in n, k² and nk taken apart they differ off
// nk = n √k²).
template <class M>
void expect_autodiff(const std::vector<std::array<double, 2>>& sets) {
    using JL = ceres::Jet<long double, 2>;
    int checked = 0;
    double worst = 0, worst_small_mu = 0;
    for (const auto& p : sets)
        for (double mu : mu_grid()) {
            double g[2];
            const double value = M::evaluate_with_gradient(p.data(), model_math::CurveNode::at(mu), g);
            ASSERT_EQ(value, M::evaluate(p.data(), mu)) << M::kId;
            const std::array<JL, 2> q{JL(p[0], 0), JL(p[1], 1)};
            const JL F = M::evaluate(q.data(), JL(mu));
            const std::array<double, 2> jet{double(F.v[0]), double(F.v[1])};
            const double scale = gradient_scale(jet.data(), 2, value);
            // Below μ = 10⁻³ the double form loses digits as 1/μ, as the Jets in double do. t = n² − k² − 1 + μ² is a
            // difference of O(1) terms, rounded by ~10⁻¹⁶ absolute (in any order of the terms): where |t| is small
            // (a dielectric-like k ≈ 0 near t = 0) that is a relative 10⁻¹⁶/|t| the long-double reference lacks.
            const double n = M::kId == models::ConductorRgb::kId ? p[0] : models::Gulbrandsen::n_of(p[0], p[1]);
            const double k2 =
                M::kId == models::ConductorRgb::kId ? p[1] * p[1] : models::Gulbrandsen::k2_of(p[0], p[1]);
            const double t = n * n - k2 - 1.0 + mu * mu;
            const double tolerance = 1e-12 * std::max(1.0, 1e-3 / mu) + 1e-16 / std::abs(t);
            for (int i = 0; i < 2; ++i) {
                ASSERT_TRUE(std::isfinite(g[i])) << M::kId << " p=(" << p[0] << ", " << p[1] << ") mu=" << mu;
                const double error = scale > 0 ? std::abs(g[i] - jet[i]) / scale : std::abs(g[i] - jet[i]);
                (mu >= 1e-3 ? worst : worst_small_mu) = std::max(mu >= 1e-3 ? worst : worst_small_mu, error);
                EXPECT_LE(error, tolerance) << M::kId << " d/d" << M::kParameters[i].name << " p=(" << p[0] << ", "
                                            << p[1] << ") mu=" << mu << ": " << g[i] << " against " << jet[i];
            }
            ++checked;
        }
    std::printf("  %s: %d points, worst difference %.2g of the gradient's scale at mu >= 1e-3, %.2g below\n",
                std::string(M::kId).c_str(), checked, worst, worst_small_mu);
}

TEST(ConductorFresnelGradient, ConductorRgbIsAutodiffOnADenseGrid) {
    std::vector<std::array<double, 2>> sets;
    for (double n : kN)
        for (double k : kK)
            if (n != 1.0 || k != 0.0) sets.push_back({n, k});  // η = 1: EtaOneReflectsNothing
    expect_autodiff<models::ConductorRgb>(sets);
    // The grid has t < 0 (k > n, or n < 1 beyond the critical angle) and t ≥ 0.
    int below = 0, above = 0;
    for (const auto& p : sets)
        for (double mu : mu_grid()) (p[0] * p[0] - p[1] * p[1] - (1 - mu * mu) < 0 ? below : above)++;
    EXPECT_GT(below, 1000);
    EXPECT_GT(above, 1000);
}

TEST(ConductorFresnelGradient, GulbrandsenIsAutodiffOnADenseGrid) {
    // r from 10⁻⁴ (r = 0 is η = 1: EtaOneReflectsNothing) to 0.995, g from 0 (k = 0, n = n_max) to 1.
    std::vector<std::array<double, 2>> sets;
    for (double r : {1e-4, 0.01, 0.04, 0.1, 0.3, 0.5, 0.7, 0.9, 0.97, 0.995})
        for (double g : {0.0, 1e-4, 0.05, 0.2, 0.4, 0.5, 0.6, 0.8, 0.95, 0.999, 1.0}) sets.push_back({r, g});
    expect_autodiff<models::Gulbrandsen>(sets);
}

// Towards r = 1 (the bound 0.99999) Gulbrandsen's map loses digits in double (n_max = (1 + √r)/(1 − √r), whose
// derivative grows as 1/(1 − √r)²), in the Jets more than in the closed form: against the Jets in long double the
// closed form is held to 10⁻¹² · (10⁻² / (1 − √r))² (at r = 0.99999, 4·10⁻⁶; measured 3·10⁻⁸, the double Jets 10⁻⁴).
TEST(ConductorFresnelGradient, GulbrandsenTowardsItsUpperBoundAgreesWithJetsToItsConditioning) {
    using JL = ceres::Jet<long double, 2>;
    for (double r : {0.99, 0.999, 0.9999, 0.99999})
        for (double g : {0.0, 0.3, 0.7, 1.0})
            for (double mu : mu_grid()) {
                if (mu < 1e-3) continue;
                const std::array<double, 2> p{r, g};
                double grad[2];
                const double value =
                    models::Gulbrandsen::evaluate_with_gradient(p.data(), model_math::CurveNode::at(mu), grad);
                EXPECT_EQ(value, models::Gulbrandsen::evaluate(p.data(), mu));
                const std::array<JL, 2> q{JL(p[0], 0), JL(p[1], 1)};
                const JL F = models::Gulbrandsen::evaluate(q.data(), JL(mu));
                const std::array<double, 2> jet{double(F.v[0]), double(F.v[1])};
                const double scale = gradient_scale(jet.data(), 2, value);
                const double condition = 1e-2 / (1.0 - std::sqrt(r));
                for (int i = 0; i < 2; ++i)
                    EXPECT_LE(std::abs(grad[i] - jet[i]), 1e-12 * condition * condition * scale)
                        << "r=" << r << " g=" << g << " mu=" << mu << " d/d" << (i ? "g" : "r");
            }
}

// η = 1 (conductor-rgb n = 1, k = 0; gulbrandsen r = 0) has no interface: F = 0 at every μ > 0, in the closed form as
// computed (t = (n² − k² − 1) + μ² is μ² exactly there, so N_s = 0), and its derivatives, which vanish, come out as
// rounding of terms of order 1/μ² that cancel: finite and below 10⁻¹⁴/μ².
TEST(ConductorFresnelGradient, EtaOneReflectsNothing) {
    for (double mu : mu_grid()) {
        if (mu <= 0.0) continue;
        double g[2];
        const std::array<double, 2> conductor{1.0, 0.0};
        EXPECT_EQ(models::ConductorRgb::evaluate_with_gradient(conductor.data(), model_math::CurveNode::at(mu), g),
                  0.0);
        for (double d : g) EXPECT_LE(std::abs(d), 1e-14 / (mu * mu)) << "mu=" << mu;
        const std::array<double, 2> gulbrandsen{0.0, 0.4};
        EXPECT_LE(
            std::abs(models::Gulbrandsen::evaluate_with_gradient(gulbrandsen.data(), model_math::CurveNode::at(mu), g)),
            1e-30);
        for (double d : g) EXPECT_LE(std::abs(d), 1e-14 / (mu * mu)) << "mu=" << mu;
    }
}

// d/dx of f at x by the fourth-order central difference in long double (f long double too).
template <class F>
long double central_difference(const F& f, long double x, long double h) {
    return (-f(x + 2 * h) + 8 * f(x + h) - 8 * f(x - h) + f(x - 2 * h)) / (12 * h);
}

// A model's evaluate_with_gradient against finite differences of its evaluate<long double> (strictly inside the
// parameter box: g = 0 is gulbrandsen's one-sided kink, which the Jet test above and ModelDerivatives cover), within
// 10⁻⁹ of the gradient's scale plus the difference's rounding.
template <class M>
void expect_finite_differences(const std::vector<std::array<double, 2>>& sets) {
    int checked = 0;
    double worst = 0;
    for (const auto& p : sets)
        for (double mu : mu_grid()) {
            double g[2];
            const double value = M::evaluate_with_gradient(p.data(), model_math::CurveNode::at(mu), g);
            EXPECT_EQ(value, M::evaluate(p.data(), mu)) << M::kId;
            const double scale = gradient_scale(g, 2, value);
            for (int i = 0; i < 2; ++i) {
                const auto at = [&](long double x) {
                    std::array<long double, 2> q{p[0], p[1]};
                    q[i] = x;
                    return M::evaluate(q.data(), static_cast<long double>(mu));
                };
                const long double h = 1e-6L * std::max(1e-2L, static_cast<long double>(std::abs(p[i])));
                const double fd = static_cast<double>(central_difference(at, p[i], h));
                // The difference's own error: truncation (h⁴), and the rounding of F (≤ 1, long double) over h.
                const double rounding = 1e-17 / static_cast<double>(h);
                const double error = std::max(0.0, std::abs(g[i] - fd) - rounding) / scale;
                worst = std::max(worst, std::abs(g[i] - fd) / scale);
                EXPECT_LE(error, 1e-9) << M::kId << " d/d" << M::kParameters[i].name << " p=(" << p[0] << ", " << p[1]
                                       << ") mu=" << mu << ": " << g[i] << " against " << fd;
                ++checked;
            }
        }
    std::printf("  %s: %d derivatives, worst difference %.2g of the gradient's scale\n", std::string(M::kId).c_str(),
                checked, worst);
}

TEST(ConductorFresnelGradient, ConductorRgbAgreesWithFiniteDifferences) {
    std::vector<std::array<double, 2>> sets;
    // k = 0 only where n > 1: a dielectric below 1 has its critical angle there, where F has a kink in n (the Jet
    // test above covers it).
    for (double n : {0.02, 0.2, 0.5, 0.95, 1.05, 1.5, 3.0, 40.0})
        for (double k : {0.0, 0.02, 0.4, 1.0, 3.0, 9.0, 200.0})
            if (k > 0 || n > 1) sets.push_back({n, k});
    expect_finite_differences<models::ConductorRgb>(sets);
}

TEST(ConductorFresnelGradient, GulbrandsenAgreesWithFiniteDifferences) {
    std::vector<std::array<double, 2>> sets;
    for (double r : {0.01, 0.04, 0.2, 0.5, 0.8, 0.95, 0.99})
        for (double g : {0.01, 0.2, 0.5, 0.8, 0.99}) sets.push_back({r, g});
    expect_finite_differences<models::Gulbrandsen>(sets);
}

}  // namespace test_conductor_gradient
}  // namespace metalfit
