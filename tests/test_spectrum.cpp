// Spectrum: construction (sorting, duplicates), linear and PCHIP interpolation, range handling.
#include <gtest/gtest.h>

#include "test_support.hpp"

#include <cmath>
#include <limits>
#include <stdexcept>
#include <string>
#include <vector>

#include "libfit/spectral/spectrum.hpp"

namespace metalfit {
namespace test_spectrum {

using namespace metalfit::test;

Spectrum make(const std::vector<double>& x, const std::vector<double>& y) {
    std::vector<SpectrumSample> s;
    for (std::size_t i = 0; i < x.size(); ++i) s.push_back({x[i], y[i]});
    return Spectrum(std::move(s));
}

// Cubic Hermite on [x0, x1] written in the monomial form a + b s + c s² + d s³ (s = x − x0), an
// independent formulation from the h00/h10/h01/h11 basis used by libfit.
double hermite(double x0, double x1, double y0, double y1, double d0, double d1, double x) {
    const double h = x1 - x0;
    const double delta = (y1 - y0) / h;
    const double c = (3.0 * delta - 2.0 * d0 - d1) / h;
    const double d = (d0 + d1 - 2.0 * delta) / (h * h);
    const double s = x - x0;
    return y0 + s * (d0 + s * (c + s * d));
}

// Natural cubic spline through (x, y) evaluated at t (tridiagonal solve for the second
// derivatives). Used only to show that the step data below makes an ordinary cubic overshoot.
double natural_cubic(const std::vector<double>& x, const std::vector<double>& y, double t) {
    const std::size_t n = x.size();
    std::vector<double> m(n, 0.0), a(n, 0.0), b(n, 0.0), c(n, 0.0), r(n, 0.0);
    b[0] = b[n - 1] = 1.0;
    for (std::size_t i = 1; i + 1 < n; ++i) {
        const double h0 = x[i] - x[i - 1], h1 = x[i + 1] - x[i];
        a[i] = h0;
        b[i] = 2.0 * (h0 + h1);
        c[i] = h1;
        r[i] = 6.0 * ((y[i + 1] - y[i]) / h1 - (y[i] - y[i - 1]) / h0);
    }
    for (std::size_t i = 1; i < n; ++i) {  // Thomas algorithm
        const double w = a[i] / b[i - 1];
        b[i] -= w * c[i - 1];
        r[i] -= w * r[i - 1];
    }
    m[n - 1] = r[n - 1] / b[n - 1];
    for (std::size_t i = n - 1; i-- > 0;) m[i] = (r[i] - c[i] * m[i + 1]) / b[i];
    std::size_t i = 0;
    while (i + 2 < n && t > x[i + 1]) ++i;
    const double h = x[i + 1] - x[i];
    const double A = (x[i + 1] - t) / h, B = (t - x[i]) / h;
    return A * y[i] + B * y[i + 1] + ((A * A * A - A) * m[i] + (B * B * B - B) * m[i + 1]) * h * h / 6.0;
}

TEST(SpectrumConstruction, SortsUnsortedInput) {
    const Spectrum s = make({700.0, 400.0, 550.0, 500.0}, {7.0, 4.0, 5.5, 5.0});
    ASSERT_EQ(s.size(), 4u);
    const std::vector<double> expected_x{400.0, 500.0, 550.0, 700.0};
    const std::vector<double> expected_y{4.0, 5.0, 5.5, 7.0};
    for (std::size_t i = 0; i < 4; ++i) {
        EXPECT_EQ(s.wavelengths()[i], expected_x[i]) << i;
        EXPECT_EQ(s.values()[i], expected_y[i]) << i;
    }
    EXPECT_EQ(s.range().min_nm, 400.0);
    EXPECT_EQ(s.range().max_nm, 700.0);
    EXPECT_EQ(s.identical_duplicates(), 0u);
    EXPECT_EQ(s.conflicting_duplicates(), 0u);
}

TEST(SpectrumConstruction, IdenticalDuplicatesAreDropped) {
    const Spectrum s = make({500.0, 400.0, 500.0, 600.0, 400.0, 500.0}, {2.0, 1.0, 2.0, 3.0, 1.0, 2.0});
    ASSERT_EQ(s.size(), 3u);
    EXPECT_EQ(s.identical_duplicates(), 3u);  // one extra 400, two extra 500
    EXPECT_EQ(s.conflicting_duplicates(), 0u);
    EXPECT_EQ(s.wavelengths()[0], 400.0);
    EXPECT_EQ(s.wavelengths()[1], 500.0);
    EXPECT_EQ(s.wavelengths()[2], 600.0);
    EXPECT_EQ(s.values()[0], 1.0);
    EXPECT_EQ(s.values()[1], 2.0);
    EXPECT_EQ(s.values()[2], 3.0);
}

TEST(SpectrumConstruction, ConflictingDuplicatesAreAveraged) {
    // Documented rule: rows with different values at one wavelength are replaced by their mean.
    const Spectrum s = make({400.0, 500.0, 600.0, 500.0, 700.0, 700.0, 700.0}, {1.0, 2.0, 3.0, 3.0, 1.0, 2.0, 6.0});
    ASSERT_EQ(s.size(), 4u);
    EXPECT_EQ(s.conflicting_duplicates(), 3u);  // one extra at 500, two extra at 700
    EXPECT_EQ(s.identical_duplicates(), 0u);
    EXPECT_DOUBLE_EQ(s.values()[1], 2.5);  // (2 + 3) / 2
    EXPECT_DOUBLE_EQ(s.values()[3], 3.0);  // (1 + 2 + 6) / 3
    EXPECT_DOUBLE_EQ(s(500.0), 2.5);
    // No zero-width step: interpolation around the averaged sample is continuous.
    EXPECT_DOUBLE_EQ(s(450.0), 1.75);
    EXPECT_DOUBLE_EQ(s(550.0), 2.75);
}

TEST(SpectrumConstruction, EmptyInputThrowsInvalidArgument) {
    EXPECT_THROW(Spectrum(std::vector<SpectrumSample>{}), std::invalid_argument);
}

TEST(SpectrumConstruction, NonFiniteSampleThrowsInvalidArgument) {
    const double nan = std::numeric_limits<double>::quiet_NaN();
    const double inf = std::numeric_limits<double>::infinity();
    EXPECT_THROW(make({400.0, nan}, {1.0, 2.0}), std::invalid_argument);
    EXPECT_THROW(make({400.0, 500.0}, {1.0, nan}), std::invalid_argument);
    EXPECT_THROW(make({400.0, inf}, {1.0, 2.0}), std::invalid_argument);
}

TEST(SpectrumLinear, EqualsTheLineBetweenTwoSamples) {
    const Spectrum s = make({400.0, 450.0, 520.0, 600.0}, {1.0, 3.0, 2.0, 2.5});
    // Between (450, 3) and (520, 2): y = 3 + (x − 450)·(2 − 3)/70.
    for (double x : {450.0, 460.0, 485.0, 500.0, 519.0, 520.0}) EXPECT_NEAR(s(x), 3.0 - (x - 450.0) / 70.0, 1e-14) << x;
    EXPECT_DOUBLE_EQ(s(485.0), 2.5);
    // Between (520, 2) and (600, 2.5).
    EXPECT_DOUBLE_EQ(s(560.0), 2.25);
    // Samples themselves are reproduced exactly.
    EXPECT_EQ(s(400.0), 1.0);
    EXPECT_EQ(s(600.0), 2.5);
    EXPECT_EQ(s(450.0, Interpolation::linear), 3.0);
}

TEST(SpectrumLinear, SingleSampleIsConstantInsideItsRange) {
    const Spectrum s = make({500.0}, {4.25});
    EXPECT_EQ(s(500.0), 4.25);
    EXPECT_EQ(s(500.0, Interpolation::pchip), 4.25);
    EXPECT_THROW(s(501.0), SpectrumRangeError);
}

TEST(SpectrumPchip, PassesThroughEverySample) {
    const std::vector<double> x{380.0, 400.0, 430.0, 500.0, 520.0, 610.0, 700.0, 830.0};
    const std::vector<double> y{0.2, 0.5, 0.4, 1.7, 2.2, 2.1, 3.9, 4.0};
    const Spectrum s = make(x, y);
    for (std::size_t i = 0; i < x.size(); ++i) EXPECT_NEAR(s(x[i], Interpolation::pchip), y[i], 1e-13) << x[i];
}

TEST(SpectrumPchip, MonotoneOnStepDataWhereCubicOvershoots) {
    const std::vector<double> x{0.0, 1.0, 2.0, 3.0, 4.0, 5.0};
    const std::vector<double> y{0.0, 0.0, 0.0, 1.0, 1.0, 1.0};
    const Spectrum s = make(x, y);
    // The data set is a real test: a natural cubic spline leaves [0, 1] and is not monotone...
    double cubic_min = 0.0, cubic_max = 1.0;
    for (double t = 0.0; t <= 5.0; t += 0.01) {
        cubic_min = std::min(cubic_min, natural_cubic(x, y, t));
        cubic_max = std::max(cubic_max, natural_cubic(x, y, t));
    }
    EXPECT_LT(cubic_min, -0.01);
    EXPECT_GT(cubic_max, 1.01);
    // ...while linear interpolation stays inside it.
    for (double t = 0.0; t <= 5.0; t += 0.01) {
        EXPECT_GE(s(t, Interpolation::linear), 0.0);
        EXPECT_LE(s(t, Interpolation::linear), 1.0);
    }
    // PCHIP: no overshoot, non-decreasing, flat where the data is flat.
    double previous = -1.0;
    for (int i = 0; i <= 500; ++i) {
        const double t = i * 0.01;
        const double v = s(t, Interpolation::pchip);
        EXPECT_GE(v, 0.0) << t;
        EXPECT_LE(v, 1.0) << t;
        EXPECT_GE(v, previous - 1e-15) << t;
        previous = v;
    }
    EXPECT_EQ(s(1.5, Interpolation::pchip), 0.0);
    EXPECT_EQ(s(3.5, Interpolation::pchip), 1.0);
    EXPECT_NEAR(s(2.5, Interpolation::pchip), 0.5, 1e-15);  // symmetric step
}

TEST(SpectrumPchip, EqualsLinearOnTwoPoints) {
    const Spectrum s = make({400.0, 700.0}, {1.0, 4.0});
    for (double x = 400.0; x <= 700.0; x += 7.5)
        EXPECT_NEAR(s(x, Interpolation::pchip), s(x, Interpolation::linear), 1e-13) << x;
    EXPECT_NEAR(s(500.0, Interpolation::pchip), 2.0, 1e-13);
}

TEST(SpectrumPchip, ReproducesAStraightLineExactly) {
    // Unequal spacing, y = 0.02 x − 3.
    const std::vector<double> x{360.0, 371.0, 400.0, 455.5, 460.0, 600.0, 830.0};
    std::vector<double> y;
    for (double xi : x) y.push_back(0.02 * xi - 3.0);
    const Spectrum s = make(x, y);
    for (double t = 360.0; t <= 830.0; t += 1.0) EXPECT_NEAR(s(t, Interpolation::pchip), 0.02 * t - 3.0, 1e-12) << t;
}

TEST(SpectrumPchip, MatchesHandComputedFritschCarlsonEqualSpacing) {
    // x = 0,1,2,3; y = 0,1,1,2. h = 1; secants δ = 1, 0, 1.
    // Interior: δ0·δ1 = 0 and δ1·δ2 = 0 → d1 = d2 = 0 (flat where the data is flat).
    // Ends (three-point, shape preserving): d0 = ((2h0 + h1)δ0 − h0δ1)/(h0 + h1) = (3·1 − 0)/2 = 1.5,
    //   same sign as δ0; |1.5| ≤ 3|δ0| → d0 = 1.5. By symmetry d3 = ((2·1 + 1)·1 − 1·0)/2 = 1.5.
    const std::vector<double> x{0.0, 1.0, 2.0, 3.0}, y{0.0, 1.0, 1.0, 2.0};
    const std::vector<double> d{1.5, 0.0, 0.0, 1.5};
    const Spectrum s = make(x, y);
    // Hand values: on [0,1] at t = 0.5: h00 = h01 = 0.5, h10 = 0.125, h11 = −0.125
    //   → 0.5·0 + 0.125·1.5 + 0.5·1 − 0.125·0 = 0.6875; on [2,3]: 0.5 + 1 − 0.125·1.5 = 1.3125.
    EXPECT_NEAR(s(0.5, Interpolation::pchip), 0.6875, 1e-15);
    EXPECT_NEAR(s(1.5, Interpolation::pchip), 1.0, 1e-15);
    EXPECT_NEAR(s(2.5, Interpolation::pchip), 1.3125, 1e-15);
    for (std::size_t i = 0; i + 1 < x.size(); ++i)
        for (double f : {0.1, 0.25, 0.5, 0.8, 0.95}) {
            const double t = x[i] + f * (x[i + 1] - x[i]);
            EXPECT_NEAR(s(t, Interpolation::pchip), hermite(x[i], x[i + 1], y[i], y[i + 1], d[i], d[i + 1], t), 1e-14)
                << t;
        }
}

TEST(SpectrumPchip, MatchesHandComputedFritschCarlsonUnequalSpacing) {
    // x = 0,1,3,4; y = 0,1,2,4. h = 1, 2, 1; δ = 1, 0.5, 2 (all positive: no extremum).
    // d1: w1 = 2h1 + h0 = 5, w2 = h1 + 2h0 = 4; (w1 + w2)/d1 = w1/δ0 + w2/δ1 = 5 + 8 = 13 → d1 = 9/13.
    // d2: w1 = 2h2 + h1 = 4, w2 = h2 + 2h1 = 5; (w1 + w2)/d2 = 4/0.5 + 5/2 = 10.5 → d2 = 9/10.5 = 6/7.
    // d0 = ((2h0 + h1)δ0 − h0δ1)/(h0 + h1) = (4 − 0.5)/3 = 7/6 (same sign as δ0, δ0·δ1 > 0: kept).
    // d3 = ((2h2 + h1)δ2 − h2δ1)/(h2 + h1) = (8 − 0.5)/3 = 2.5 (kept likewise).
    const std::vector<double> x{0.0, 1.0, 3.0, 4.0}, y{0.0, 1.0, 2.0, 4.0};
    const std::vector<double> d{7.0 / 6.0, 9.0 / 13.0, 6.0 / 7.0, 2.5};
    // Scale x to nanometres to exercise a realistic grid: x_nm = 400 + 50x, slopes per nm = d/50.
    std::vector<double> x_nm;
    for (double xi : x) x_nm.push_back(400.0 + 50.0 * xi);
    const Spectrum s = make(x_nm, y);
    for (std::size_t i = 0; i + 1 < x.size(); ++i)
        for (double f : {0.0, 0.1, 0.3, 0.5, 0.7, 0.9, 1.0}) {
            const double t = x[i] + f * (x[i + 1] - x[i]);
            const double expected = hermite(x[i], x[i + 1], y[i], y[i + 1], d[i], d[i + 1], t);
            EXPECT_NEAR(s(400.0 + 50.0 * t, Interpolation::pchip), expected, 1e-12) << t;
        }
    // One value worked fully by hand: midpoint of [1,3], s = 1, h = 2:
    //   y = 1 + d1·1 + c·1 + dd·1 with δ = 0.5, c = (1.5 − 18/13 − 6/7)/2, dd = (9/13 + 6/7 − 1)/4.
    const double c = (1.5 - 18.0 / 13.0 - 6.0 / 7.0) / 2.0, dd = (9.0 / 13.0 + 6.0 / 7.0 - 1.0) / 4.0;
    EXPECT_NEAR(s(500.0, Interpolation::pchip), 1.0 + 9.0 / 13.0 + c + dd, 1e-12);
}

TEST(SpectrumRange, OutOfRangeThrowsNamingWavelengthAndRange) {
    const Spectrum s = make({400.0, 550.0, 700.0}, {1.0, 2.0, 3.0});
    try {
        (void)s(912.5);
        FAIL() << "expected SpectrumRangeError";
    } catch (const SpectrumRangeError& e) {
        const std::string what = e.what();
        EXPECT_TRUE(Contains(what, "912.5"));
        EXPECT_TRUE(Contains(what, "400"));
        EXPECT_TRUE(Contains(what, "700"));
        EXPECT_EQ(what.find('\n'), std::string::npos);
        EXPECT_EQ(e.requested_nm, 912.5);
        EXPECT_EQ(e.range.min_nm, 400.0);
        EXPECT_EQ(e.range.max_nm, 700.0);
    }
    EXPECT_THROW((void)s(399.999), SpectrumRangeError);
    EXPECT_THROW((void)s(399.999, Interpolation::pchip), SpectrumRangeError);
    EXPECT_THROW((void)s(700.001, Interpolation::linear, OutOfRange::error), SpectrumRangeError);
    // SpectrumRangeError is a std::domain_error.
    EXPECT_THROW((void)s(1000.0), std::domain_error);
    // Range ends are inside.
    EXPECT_NO_THROW((void)s(400.0));
    EXPECT_NO_THROW((void)s(700.0));
}

TEST(SpectrumRange, ClampReturnsEndValues) {
    const Spectrum s = make({400.0, 550.0, 700.0}, {1.0, 2.0, 3.0});
    EXPECT_EQ(s(300.0, Interpolation::linear, OutOfRange::clamp), 1.0);
    EXPECT_EQ(s(399.999, Interpolation::pchip, OutOfRange::clamp), 1.0);
    EXPECT_EQ(s(700.5, Interpolation::linear, OutOfRange::clamp), 3.0);
    EXPECT_EQ(s(1e6, Interpolation::pchip, OutOfRange::clamp), 3.0);
    // Inside the range clamp changes nothing.
    EXPECT_DOUBLE_EQ(s(475.0, Interpolation::linear, OutOfRange::clamp), 1.5);
}

TEST(SpectrumRange, NanWavelengthThrows) {
    const Spectrum s = make({400.0, 700.0}, {1.0, 3.0});
    const double nan = std::numeric_limits<double>::quiet_NaN();
    EXPECT_THROW((void)s(nan), SpectrumRangeError);
    EXPECT_THROW((void)s(nan, Interpolation::pchip), SpectrumRangeError);
    // Clamping cannot give a NaN wavelength a meaning either.
    EXPECT_THROW((void)s(nan, Interpolation::linear, OutOfRange::clamp), SpectrumRangeError);
}

TEST(SpectrumRange, CountInIsInclusive) {
    const Spectrum s = make({350.0, 360.0, 400.0, 500.0, 830.0, 831.0}, {1, 1, 1, 1, 1, 1});
    EXPECT_EQ(s.count_in(kVisibleRange), 4u);  // 360, 400, 500, 830
    EXPECT_EQ(s.count_in({400.0, 500.0}), 2u);
    EXPECT_EQ(s.count_in({401.0, 499.0}), 0u);
    EXPECT_EQ(s.count_in({0.0, 1e9}), 6u);
}

TEST(SpectrumRange, WavelengthRangeHelpers) {
    const WavelengthRange r{400.0, 700.0};
    EXPECT_TRUE(r.contains(400.0));
    EXPECT_TRUE(r.contains(700.0));
    EXPECT_FALSE(r.contains(700.0001));
    EXPECT_FALSE(r.covers(kVisibleRange));
    EXPECT_TRUE((WavelengthRange{300.0, 900.0}).covers(kVisibleRange));
    EXPECT_TRUE(kVisibleRange.covers(kVisibleRange));
}

}  // namespace test_spectrum
}  // namespace metalfit
