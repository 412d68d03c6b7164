// Exact Fresnel reflectance: checked against independent closed forms, limits and a dense sweep.
#include <gtest/gtest.h>

#include <cmath>
#include <complex>
#include <numbers>

#include "libfit/optics/fresnel.hpp"

namespace metalfit {
namespace test_fresnel {

using C = std::complex<double>;

// The thesis' real form (Lazányi 2008, ch. 3; docs/colour.md, "Exact Fresnel reflectance"), valid for μ > 0: an independent route to F.
double thesis_real_form(double mu, double n, double k) {
    const double s2 = 1.0 - mu * mu, s = std::sqrt(s2);
    const double t = n * n - k * k - s2;
    const double root = std::sqrt(t * t + 4.0 * n * n * k * k);
    const double a2 = 0.5 * (root + t), b2 = 0.5 * (root - t), a = std::sqrt(a2);
    const double fs = (a2 + b2 - 2.0 * a * mu + mu * mu) / (a2 + b2 + 2.0 * a * mu + mu * mu);
    const double q = s * (s / mu);
    const double fp = fs * (a2 + b2 - 2.0 * a * q + q * q) / (a2 + b2 + 2.0 * a * q + q * q);
    return 0.5 * (fs + fp);
}

TEST(Fresnel, NormalIncidenceMatchesClosedForm) {
    for (double n : {0.05, 0.2, 0.5, 1.0, 1.5, 3.0, 8.0})
        for (double k : {0.0, 0.01, 1.0, 3.5, 10.0, 1000.0}) {
            const double expected = ((n - 1) * (n - 1) + k * k) / ((n + 1) * (n + 1) + k * k);
            EXPECT_NEAR(fresnel(1.0, {n, k}), expected, 1e-14 + 1e-13 * expected) << "n=" << n << " k=" << k;
            EXPECT_DOUBLE_EQ(fresnel_normal_incidence({n, k}), expected);
            // At normal incidence s and p coincide.
            const auto r = fresnel_reflectance(1.0, {n, k});
            EXPECT_NEAR(r.s, r.p, 1e-14);
        }
}

TEST(Fresnel, GrazingIncidenceReflectsEverything) {
    for (C eta :
         {C(0.2, 3.0), C(1.5, 0.0), C(0.5, 0.0), C(0.05, 0.0), C(1.0, 1e-9), C(1.0 + 1e-9, 0.0), C(1.1, 1000.0)}) {
        const auto r = fresnel_reflectance(0.0, eta);
        EXPECT_DOUBLE_EQ(r.s, 1.0) << eta;
        EXPECT_DOUBLE_EQ(r.p, 1.0) << eta;
    }
}

TEST(Fresnel, ConductorMatchesThesisRealForm) {
    for (double n : {0.1, 0.27, 1.0, 1.5, 2.9})
        for (double k : {0.5, 2.8, 3.6, 7.0})
            for (double mu : {1e-3, 0.05, 1.0 / 7.0, 0.3, 0.5, 0.8, 1.0})
                EXPECT_NEAR(fresnel(mu, {n, k}), thesis_real_form(mu, n, k), 1e-12)
                    << "n=" << n << " k=" << k << " mu=" << mu;
}

// Dielectric (k = 0) reference from Snell's law and the angle forms of the Fresnel equations:
// R_s = sin²(θi − θt)/sin²(θi + θt), R_p = tan²(θi − θt)/tan²(θi + θt); 1 beyond the critical angle.
FresnelReflectance snell(double mu, double n) {
    const double ti = std::acos(mu);
    const double sin_t = std::sin(ti) / n;
    if (sin_t >= 1.0) return {1.0, 1.0};
    const double tt = std::asin(sin_t);
    const double rs = std::sin(ti - tt) / std::sin(ti + tt);
    const double rp = std::tan(ti - tt) / std::tan(ti + tt);
    return {rs * rs, rp * rp};
}

TEST(Fresnel, DielectricMatchesSnellIncludingTotalInternalReflection) {
    for (double n : {1.5, 1.333, 2.4, 0.9, 0.66, 0.2})
        for (double mu : {0.02, 0.1, 0.3, 0.45, 0.6, 0.75, 0.9, 0.99}) {
            const auto expected = snell(mu, n);
            const auto r = fresnel_reflectance(mu, {n, 0.0});
            EXPECT_NEAR(r.s, expected.s, 1e-12) << "n=" << n << " mu=" << mu;
            EXPECT_NEAR(r.p, expected.p, 1e-12) << "n=" << n << " mu=" << mu;
        }
}

TEST(Fresnel, TotalInternalReflectionBelowCriticalAngle) {
    const double n = 0.66;  // e.g. glass → air seen from inside, relative index 1/1.5
    const double mu_critical = std::sqrt(1.0 - n * n);
    EXPECT_DOUBLE_EQ(fresnel(mu_critical * 0.999, {n, 0.0}), 1.0);
    EXPECT_LT(fresnel(mu_critical * 1.01, {n, 0.0}), 1.0);
}

TEST(Fresnel, BrewsterAngleHasNoParallelReflection) {
    const double n = 1.5;
    const double mu_brewster = std::cos(std::atan(n));
    const auto r = fresnel_reflectance(mu_brewster, {n, 0.0});
    EXPECT_NEAR(r.p, 0.0, 1e-15);
    EXPECT_GT(r.s, 0.1);
}

TEST(Fresnel, NoInterfaceReflectsNothing) {
    for (double mu : {0.0, 1e-9, 0.1, 0.5, 1.0}) EXPECT_EQ(fresnel(mu, {1.0, 0.0}), 0.0) << mu;
}

TEST(Fresnel, HugeExtinctionIsAlmostAPerfectMirror) {
    // k = 1000: both forms agree, F stays in (0.99, 1] except in the pseudo-Brewster dip of the p
    // polarisation near μ ≈ 1/|η|, and 1 − F(1) = 4n / ((n + 1)² + k²).
    for (double mu : {1e-3, 0.01, 0.1, 0.5, 1.0}) {
        const double f = fresnel(mu, {2.0, 1000.0});
        EXPECT_NEAR(f, thesis_real_form(mu, 2.0, 1000.0), 1e-12) << mu;
        EXPECT_GT(f, 0.99) << mu;
        EXPECT_LE(f, 1.0) << mu;
    }
    EXPECT_LT(fresnel_reflectance(1e-3, {2.0, 1000.0}).p, 0.999);  // the dip exists
    EXPECT_NEAR(1.0 - fresnel(1.0, {2.0, 1000.0}), 4.0 * 2.0 / (9.0 + 1e6), 1e-15);
}

TEST(Fresnel, ContinuousAtBothEnds) {
    for (C eta : {C(0.18, 3.4), C(1.5, 0.0), C(0.6, 0.0), C(1.09, 6.8)}) {
        EXPECT_NEAR(fresnel(1e-9, eta), fresnel(0.0, eta), 1e-6) << eta;
        EXPECT_NEAR(fresnel(1.0 - 1e-12, eta), fresnel(1.0, eta), 1e-9) << eta;
    }
}

TEST(Fresnel, DenseSweepStaysFiniteAndInUnitInterval) {
    // 101 n (log-spaced 0.01…10) × 100 k (0 and log-spaced 1e-4…100) × 101 μ (both ends) ≈ 1.02e6.
    long samples = 0, bad = 0;
    for (int i = 0; i <= 100; ++i) {
        const double n = 0.01 * std::pow(1000.0, i / 100.0);
        for (int j = 0; j < 100; ++j) {
            const double k = j == 0 ? 0.0 : 1e-4 * std::pow(1e6, (j - 1) / 98.0);
            for (int m = 0; m <= 100; ++m) {
                const double mu = m / 100.0;
                const auto r = fresnel_reflectance(mu, {n, k});
                const double f = r.unpolarized();
                ++samples;
                const bool ok =
                    std::isfinite(f) && f >= 0.0 && f <= 1.0 && r.s >= 0.0 && r.s <= 1.0 && r.p >= 0.0 && r.p <= 1.0;
                if (!ok && ++bad < 10) ADD_FAILURE() << "n=" << n << " k=" << k << " mu=" << mu << " F=" << f;
            }
        }
    }
    EXPECT_GE(samples, 1000000);
    EXPECT_EQ(bad, 0);
}

}  // namespace test_fresnel
}  // namespace metalfit
