// line_minimum: the bounded 1-D local minimum from a start (bracketing downhill, then Brent's zeroin on the
// derivative), against minima known in closed form, on bounds, in the valley of the start, and with minima known
// before (the same valley not refined twice).
#include <gtest/gtest.h>

#include <cmath>
#include <limits>
#include <numbers>
#include <vector>

#include "libfit/base/line_minimum.hpp"

namespace metalfit {
namespace test_line_minimum {

// Counts its evaluations, so that the search's own count can be checked.
struct Counted {
    double (*value)(double);
    double (*slope)(double);
    int calls = 0;
    LinePoint operator()(double x) {
        ++calls;
        return {x, value(x), slope(x)};
    }
};

double log_parabola(double x) { return std::pow(std::log(x) - std::log(3.0), 2); }
double log_parabola_slope(double x) { return 2 * (std::log(x) - std::log(3.0)) / x; }

TEST(LineMinimum, FindsTheMinimumFromEitherSide) {
    for (double x0 : {0.05, 0.1, 2.9, 3.2, 50.0, 64.0}) {
        Counted f{log_parabola, log_parabola_slope};
        const LineMinimum m = line_minimum(f, x0, 0.05, 64.0);
        EXPECT_TRUE(m.converged) << x0;
        EXPECT_NEAR(m.minimum.x, 3.0, 1e-11 * 3.0) << x0;
        EXPECT_EQ(m.start.x, x0);
        EXPECT_EQ(m.start.value, log_parabola(x0));
        EXPECT_EQ(m.evaluations, f.calls - 1) << x0;  // after the start's
        EXPECT_LT(m.evaluations, 30) << x0;
        EXPECT_EQ(m.same_as, -1);
    }
}

double rising(double x) { return x; }
double one(double) { return 1; }
double falling(double x) { return -x; }
double minus_one(double) { return -1; }

TEST(LineMinimum, EndsExactlyOnTheBoundTheSlopePointsOutOf) {
    Counted up{rising, one};
    const LineMinimum low = line_minimum(up, 5.0, 0.05, 64.0);
    EXPECT_TRUE(low.converged);
    EXPECT_EQ(low.minimum.x, 0.05);
    Counted down{falling, minus_one};
    const LineMinimum high = line_minimum(down, 5.0, 0.05, 64.0);
    EXPECT_TRUE(high.converged);
    EXPECT_EQ(high.minimum.x, 64.0);
    // A start outside the bounds is clamped first.
    Counted again{falling, minus_one};
    EXPECT_EQ(line_minimum(again, 100.0, 0.05, 64.0).start.x, 64.0);
}

double wave(double x) { return std::sin(x); }
double wave_slope(double x) { return std::cos(x); }

// Where the steps stay short of the next ridge (a step may cross it where the next valley is lower: from 2, the
// third step lands at 16.3, below the start, and the search ends at 11π/2).
TEST(LineMinimum, StaysInTheValleyOfItsStart) {
    // sin on [0.5, 20]: minima at 3π/2 and 7π/2, the maximum between them at 5π/2.
    constexpr double pi = std::numbers::pi;
    Counted left{wave, wave_slope};
    const LineMinimum a = line_minimum(left, 6.0, 0.5, 20.0);
    EXPECT_NEAR(a.minimum.x, 1.5 * pi, 1e-11 * 1.5 * pi);
    Counted right{wave, wave_slope};
    const LineMinimum b = line_minimum(right, 9.0, 0.5, 20.0);
    EXPECT_NEAR(b.minimum.x, 3.5 * pi, 1e-11 * 3.5 * pi);
}

double tilted_wave(double x) { return std::sin(x) + 0.2 * x; }
double tilted_wave_slope(double x) { return std::cos(x) + 0.2; }

TEST(LineMinimum, AStepLandingHigherAcrossARidgeIsHalved) {
    // From 2 the third step lands at 16.3, in a higher valley: halved until it stays in the start's, whose minimum is
    // at cos x = −0.2, x = π + acos 0.2.
    Counted f{tilted_wave, tilted_wave_slope};
    const LineMinimum m = line_minimum(f, 2.0, 0.5, 20.0);
    const double expected = std::numbers::pi + std::acos(0.2);
    EXPECT_TRUE(m.converged);
    EXPECT_NEAR(m.minimum.x, expected, 1e-11 * expected);
}

TEST(LineMinimum, ABracketHoldingAKnownMinimumIsNotRefined) {
    constexpr double pi = std::numbers::pi;
    const std::vector<double> known{3.5 * pi, 1.5 * pi};
    Counted same{wave, wave_slope};
    const LineMinimum m = line_minimum(same, 5.5, 0.5, 20.0, known);
    EXPECT_EQ(m.same_as, 1);
    EXPECT_TRUE(m.converged);
    Counted refined{wave, wave_slope};
    const LineMinimum full = line_minimum(refined, 5.5, 0.5, 20.0);
    EXPECT_LT(m.evaluations, full.evaluations);
    // Another valley: refined as without them.
    Counted other{wave, wave_slope};
    const LineMinimum o = line_minimum(other, 3.0, 0.5, 20.0, std::vector<double>{3.5 * pi});
    EXPECT_EQ(o.same_as, -1);
    EXPECT_NEAR(o.minimum.x, 1.5 * pi, 1e-11 * 1.5 * pi);
}

double nan_slope(double) { return std::numeric_limits<double>::quiet_NaN(); }

TEST(LineMinimum, ANonFiniteSlopeAtTheStartIsNotConvergence) {
    Counted f{rising, nan_slope};
    const LineMinimum m = line_minimum(f, 2.0, 0.05, 64.0);
    EXPECT_FALSE(m.converged);
    EXPECT_EQ(m.minimum.x, 2.0);
    EXPECT_EQ(m.evaluations, 0);
}

}  // namespace test_line_minimum
}  // namespace metalfit
