// The real, branch-free Fresnel form (optics/fresnel_real.hpp) against the complex form (optics/fresnel.hpp), which
// stays the independent check: conductors, dielectrics with n above and below 1 (total internal reflection), the
// limits, float and double.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <complex>

#include "libfit/optics/fresnel.hpp"
#include "libfit/optics/fresnel_real.hpp"

namespace metalfit {
namespace test_fresnel_real {

using C = std::complex<double>;

// n, k spanning the catalog (silver's n ≈ 0.05 and k ≈ 4, aluminium's k ≈ 7–9, k up to 1000) and dielectrics.
const double kN[] = {0.03, 0.05, 0.2, 0.5, 0.9, 1.0, 1.1, 1.5, 2.5, 4.0, 8.0};
const double kK[] = {0.0, 1e-8, 0.01, 0.3, 1.0, 3.5, 7.0, 10.0, 100.0, 1000.0};

double relative_difference(double a, double b) { return std::abs(a - b) / std::max(std::abs(b), 1e-300); }

// The complex form of fresnel.hpp in long double (64-bit significand): a closer truth where the double complex form
// itself loses digits (η near 1, where 1 − sin²θ/η² cancels).
double complex_form_long_double(double mu_in, C eta_in) {
    using L = std::complex<long double>;
    const L eta(eta_in.real(), eta_in.imag());
    const long double mu = mu_in, sin2 = (1.0L - mu) * (1.0L + mu);
    const L cos_t = std::sqrt(L(1.0L, 0.0L) - sin2 / (eta * eta));
    const L rs = (mu - eta * cos_t) / (mu + eta * cos_t), rp = (eta * mu - cos_t) / (eta * mu + cos_t);
    return double(0.5L * (std::min(std::norm(rs), 1.0L) + std::min(std::norm(rp), 1.0L)));
}

TEST(FresnelReal, MatchesTheComplexFormToRoundingOverConductorsAndDielectrics) {
    double worst = 0.0;
    for (double n : kN)
        for (double k : kK) {
            const C eta(n, k);
            if (eta == C(1.0, 0.0)) continue;
            const SquaredIndex<double> e = squared_index(eta);
            // Where F < 0.01 (media near vacuum: n = 1 with small k, dielectrics near Brewster's angle) F is
            // ill-conditioned in both forms (relative condition ~ 1/F): there the real form is held to 1e-14 absolute
            // against the long double complex form. Every conductor of the catalog reflects more than 0.01.
            for (int i = 0; i <= 2000; ++i) {
                const double mu = i / 2000.0, got = fresnel_real(mu, e);
                if (fresnel(mu, eta) < 0.01) {
                    ASSERT_NEAR(got, complex_form_long_double(mu, eta), 1e-14)
                        << "n " << n << " k " << k << " mu " << mu;
                    continue;
                }
                const double d = relative_difference(got, fresnel(mu, eta));
                worst = std::max(worst, d);
                ASSERT_LE(d, 1e-12) << "n " << n << " k " << k << " mu " << mu << ": " << got << " vs "
                                    << fresnel(mu, eta);
            }
        }
    EXPECT_GT(worst, 0.0)
        << "the two forms round differently somewhere; identical everywhere would mean one is tested against itself";
}

TEST(FresnelReal, LimitsAsTheComplexForm) {
    // η = 1 reflects nothing at every μ, grazing included (no 0/0).
    for (double mu : {0.0, 0.3, 1.0}) EXPECT_EQ(fresnel_real(mu, squared_index(C(1.0, 0.0))), 0.0) << mu;
    // Grazing incidence reflects everything for every other η; μ outside [0, 1] is clamped.
    for (double n : kN)
        for (double k : kK) {
            if (n == 1.0 && k == 0.0) continue;
            const SquaredIndex<double> e = squared_index(C(n, k));
            EXPECT_DOUBLE_EQ(fresnel_real(0.0, e), 1.0) << n << " " << k;
            EXPECT_EQ(fresnel_real(-0.5, e), fresnel_real(0.0, e));
            EXPECT_EQ(fresnel_real(1.5, e), fresnel_real(1.0, e));
        }
    // Total internal reflection (n < 1, k = 0, below the critical μ): exactly 1, never above.
    const SquaredIndex<double> e = squared_index(C(0.5, 0.0));
    for (double mu : {0.1, 0.5, 0.8}) EXPECT_EQ(fresnel_real(mu, e), 1.0) << mu;
    // NaN stays visible.
    EXPECT_TRUE(std::isnan(fresnel_real(0.5, squared_index(C(std::nan(""), 3.0)))));
}

TEST(FresnelReal, FloatFollowsDoubleToFloatRounding) {
    for (double n : kN)
        for (double k : kK) {
            if (n == 1.0 && k == 0.0) continue;
            const SquaredIndex<float> ef = squared_index<float>(C(n, k));
            for (int i = 0; i <= 100; ++i) {
                const double mu = i / 100.0;
                EXPECT_NEAR(fresnel_real(float(mu), ef), fresnel(mu, C(n, k)), 2e-5) << n << " " << k << " " << mu;
            }
        }
}

// The import range of n and k (io: n, k <= 1e6 and |n + ik| >= 1e-6, docs/data.md) is where both double forms stay
// exact: at its corners and edges within 4e-15 of the long-double form at every μ. Just outside it they are not:
// |η²|² overflows at n or k ≈ 1e77 (NaN), and near η = 0 the μ = 1 end loses its digits.
TEST(FresnelReal, ExactInsideTheImportRange) {
    const double edge[][2] = {{1e6, 0.0},  {0.0, 1e6},   {1e6, 1e6},  {1e6, 1e-6}, {1e-6, 1e6}, {1e-6, 0.0},
                              {0.0, 1e-6}, {1e-6, 1e-6}, {1e-6, 3.0}, {0.05, 1e6}, {1e3, 1e3}};
    double worst = 0.0;
    for (const auto& [n, k] : edge) {
        const SquaredIndex<double> e = squared_index(C(n, k));
        for (int i = 0; i <= 256; ++i) {
            const double mu = i / 256.0, truth = complex_form_long_double(mu, C(n, k));
            ASSERT_TRUE(std::isfinite(fresnel_real(mu, e)) && std::isfinite(fresnel(mu, C(n, k)))) << n << " " << k;
            worst = std::max({worst, relative_difference(fresnel_real(mu, e), truth),
                              relative_difference(fresnel(mu, C(n, k)), truth)});
        }
    }
    EXPECT_LT(worst, 4e-15);
    // Outside: NaN at 1e78 (what the reference curves integrate), and a reflectance off by a factor near |η| = 1e-80
    // (the real form's μ = 1 end).
    EXPECT_TRUE(std::isnan(fresnel_real(0.5, squared_index(C(1e78, 1e78)))));
    EXPECT_GT(relative_difference(fresnel_real(1.0, squared_index(C(1e-80, 0.0))),
                                  complex_form_long_double(1.0, C(1e-80, 0.0))),
              0.1);
}

}  // namespace test_fresnel_real
}  // namespace metalfit
