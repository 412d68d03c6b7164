// The sheet's signed false-colour error view (issue 36 item 1): the relative luminance error against a direct
// computation, the scale chosen from the data, the colours' sign and order, the colour bar.
#include <gtest/gtest.h>

#include <cmath>

#include "glpreview/render/error_view.hpp"

namespace metalfit::test {
namespace test_preview_error_view {

using namespace metalfit::glpreview;

// Rec. 709 / sRGB primaries' luminance (IEC 61966-2-1).
const LuminanceWeights kRec709{0.2126, 0.7152, 0.0722};

double brightness(const RGB& c) { return c.r + c.g + c.b; }

TEST(ErrorView, RelativeLuminanceErrorIsTheRatioOfLuminancesMinusOne) {
    Image reference(3, 2), model(3, 2);
    const std::vector<RGB> ref{{0.5, 0.4, 0.3}, {0.9, 0.1, 0.1},    {0.0, 0.0, 0.0},
                               {0.2, 0.2, 0.2}, {1e-8, 1e-8, 1e-8}, {0.1, 0.7, 0.05}};
    const std::vector<RGB> mod{{0.5005, 0.4004, 0.3003}, {0.9, 0.1, 0.2}, {0.3, 0.3, 0.3},
                               {0.19, 0.2, 0.2},         {1.0, 1.0, 1.0}, {0.1, 0.7, 0.05}};
    for (int i = 0; i < 6; ++i) {
        reference.set(i % 3, i / 3, ref[i]);
        model.set(i % 3, i / 3, mod[i]);
    }
    const std::vector<double> e = relative_luminance_error(model, reference, kRec709);
    ASSERT_EQ(e.size(), 6u);
    EXPECT_NEAR(e[0], 1e-3, 1e-6);  // every channel 0.1 % brighter (float pixels: 1e-7 relative)
    // Blue only: 0.1 of blue weighs 0.00722 against Y = 0.9·0.2126 + 0.1·0.7152 + 0.1·0.0722.
    EXPECT_NEAR(e[1], 0.00722 / (0.9 * 0.2126 + 0.07152 + 0.00722), 1e-6);
    EXPECT_EQ(e[2], 0.0) << "a black reference has no relative error";
    EXPECT_NEAR(e[3], -0.01 * 0.2126 / 0.2, 1e-6);
    EXPECT_EQ(e[4], 0.0) << "darker than kErrorViewDarkReference";
    EXPECT_EQ(e[5], 0.0);
}

TEST(ErrorView, TheScaleIsTheDecadeAboveTheErrorsSpanningFourDecades) {
    std::vector<double> errors(1000, 0.0);
    for (int i = 0; i < 1000; ++i) errors[i] = (i % 2 ? -1 : 1) * 3e-3 * (i + 1) / 1000.0;
    ErrorScale s = error_scale_from(errors);  // 99.5th percentile of |e| ≈ 2.99e-3
    EXPECT_DOUBLE_EQ(s.largest, 1e-2);
    EXPECT_DOUBLE_EQ(s.smallest, 1e-5) << "four decades down is 1e-6: floored at kErrorViewFloor";
    EXPECT_DOUBLE_EQ(error_scale_from(std::vector<double>(10, 0.0)).largest, kErrorViewLowestTop)
        << "a perfect fit still gets a scale where 0.1 % would show";
    EXPECT_DOUBLE_EQ(error_scale_from({0.02, -0.5, 0.3}).largest, 1.0);
    EXPECT_DOUBLE_EQ(error_scale_from({5.0, -7.0}).largest, 1.0) << "the top is at most 100 %";
    s = error_scale_from({0.05, -0.04});
    EXPECT_DOUBLE_EQ(s.largest, 0.1);
    EXPECT_DOUBLE_EQ(s.smallest, 1e-5);
    EXPECT_EQ(scale_label(s), "+-1e-05..0.1 log");
}

TEST(ErrorView, ColoursAreBlackAtZeroWarmAboveColdBelowAndBrighterWithTheError) {
    const ErrorScale scale{1e-5, 1e-1};
    EXPECT_EQ(brightness(error_colour(0.0, scale)), 0.0);
    EXPECT_EQ(brightness(error_colour(5e-6, scale)), 0.0) << "below the scale's bottom";
    double previous = 0;
    for (double e = 2e-5; e <= 0.1; e *= 2) {
        const RGB warm = error_colour(e, scale), cold = error_colour(-e, scale);
        EXPECT_GT(warm.r, warm.b) << e;
        EXPECT_GT(cold.b, cold.r) << e;
        EXPECT_GT(brightness(warm), previous) << e;
        previous = brightness(warm);
    }
    // A 0.1 % error is a quarter of the way up a scale that reaches 10 %: plainly not black.
    EXPECT_GT(brightness(error_colour(1e-3, error_scale_from({0.05}))), 0.2);
    EXPECT_EQ(brightness(error_colour(10.0, scale)), brightness(error_colour(0.1, scale))) << "clamped at the top";
}

TEST(ErrorView, TheColourBarRunsFromPlusToMinusTheScaleThroughBlack) {
    const ErrorScale scale{1e-5, 1e-1};
    Image image(10, 41);
    paint_colour_bar(image, 2, 0, 4, 41, scale);
    const RGB top = image.at(3, 0), middle = image.at(3, 20), bottom = image.at(3, 40);
    const RGB plus = error_colour(0.1, scale), minus = error_colour(-0.1, scale);
    EXPECT_NEAR(top.r, plus.r, 1e-6);
    EXPECT_NEAR(top.b, plus.b, 1e-6);
    EXPECT_NEAR(bottom.r, minus.r, 1e-6);
    EXPECT_NEAR(bottom.b, minus.b, 1e-6);
    EXPECT_EQ(brightness(middle), 0.0);
    EXPECT_EQ(brightness(image.at(0, 0)), 0.0) << "nothing painted outside the bar";
    EXPECT_EQ(brightness(image.at(6, 0)), 0.0);
    // Rows a quarter of the way down show an error two decades below the top (t = 0.5).
    const RGB quarter = image.at(3, 10);
    const RGB expected = error_colour(1e-3, scale);
    EXPECT_NEAR(quarter.r, expected.r, 1e-6);
}

}  // namespace test_preview_error_view
}  // namespace metalfit::test
