// CIE L*a*b* and CIEDE2000: Sharma, Wu and Dalal's published test data, symmetry, and the
// L*a*b* anchors (white, 18 % grey, neutrals, the ε branch point).
#include <gtest/gtest.h>

#include <cmath>
#include <numbers>

#include "libfit/color/color_difference.hpp"

namespace metalfit {
namespace {

struct SharmaPair {
    Lab first, second;
    double delta_e00;
};

// G. Sharma, W. Wu, E. N. Dalal, "The CIEDE2000 color-difference formula: implementation notes,
// supplementary test data, and mathematical observations", Color Res. Appl. 30(1), 2005, Table 1.
// Pairs 1–6: true chroma / hue differences; 7–16: arctangent and mean-hue edge cases (neutrals,
// hues straddling 0°/180°); 17–20: large differences; 21–34: CIE technical report pairs.
constexpr SharmaPair kSharma[] = {
    {{50.0000, 2.6772, -79.7751}, {50.0000, 0.0000, -82.7485}, 2.0425},   // 1
    {{50.0000, 3.1571, -77.2803}, {50.0000, 0.0000, -82.7485}, 2.8615},   // 2
    {{50.0000, 2.8361, -74.0200}, {50.0000, 0.0000, -82.7485}, 3.4412},   // 3
    {{50.0000, -1.3802, -84.2814}, {50.0000, 0.0000, -82.7485}, 1.0000},  // 4
    {{50.0000, -1.1848, -84.8006}, {50.0000, 0.0000, -82.7485}, 1.0000},  // 5
    {{50.0000, -0.9009, -85.5211}, {50.0000, 0.0000, -82.7485}, 1.0000},  // 6
    {{50.0000, 0.0000, 0.0000}, {50.0000, -1.0000, 2.0000}, 2.3669},      // 7
    {{50.0000, -1.0000, 2.0000}, {50.0000, 0.0000, 0.0000}, 2.3669},      // 8
    {{50.0000, 2.4900, -0.0010}, {50.0000, -2.4900, 0.0009}, 7.1792},     // 9
    {{50.0000, 2.4900, -0.0010}, {50.0000, -2.4900, 0.0010}, 7.1792},     // 10
    {{50.0000, 2.4900, -0.0010}, {50.0000, -2.4900, 0.0011}, 7.2195},     // 11
    {{50.0000, 2.4900, -0.0010}, {50.0000, -2.4900, 0.0012}, 7.2195},     // 12
    {{50.0000, -0.0010, 2.4900}, {50.0000, 0.0009, -2.4900}, 4.8045},     // 13
    {{50.0000, -0.0010, 2.4900}, {50.0000, 0.0010, -2.4900}, 4.8045},     // 14
    {{50.0000, -0.0010, 2.4900}, {50.0000, 0.0011, -2.4900}, 4.7461},     // 15
    {{50.0000, 2.5000, 0.0000}, {50.0000, 0.0000, -2.5000}, 4.3065},      // 16
    {{50.0000, 2.5000, 0.0000}, {73.0000, 25.0000, -18.0000}, 27.1492},   // 17
    {{50.0000, 2.5000, 0.0000}, {61.0000, -5.0000, 29.0000}, 22.8977},    // 18
    {{50.0000, 2.5000, 0.0000}, {56.0000, -27.0000, -3.0000}, 31.9030},   // 19
    {{50.0000, 2.5000, 0.0000}, {58.0000, 24.0000, 15.0000}, 19.4535},    // 20
    {{50.0000, 2.5000, 0.0000}, {50.0000, 3.1736, 0.5854}, 1.0000},       // 21
    {{50.0000, 2.5000, 0.0000}, {50.0000, 3.2972, 0.0000}, 1.0000},       // 22
    {{50.0000, 2.5000, 0.0000}, {50.0000, 1.8634, 0.5757}, 1.0000},       // 23
    {{50.0000, 2.5000, 0.0000}, {50.0000, 3.2592, 0.3350}, 1.0000},       // 24
    {{60.2574, -34.0099, 36.2677}, {60.4626, -34.1751, 39.4387}, 1.2644}, // 25
    {{63.0109, -31.0961, -5.8663}, {62.8187, -29.7946, -4.0864}, 1.2630}, // 26
    {{61.2901, 3.7196, -5.3901}, {61.4292, 2.2480, -4.9620}, 1.8731},     // 27
    {{35.0831, -44.1164, 3.7933}, {35.0232, -40.0716, 1.5901}, 1.8645},   // 28
    {{22.7233, 20.0904, -46.6940}, {23.0331, 14.9730, -42.5619}, 2.0373}, // 29
    {{36.4612, 47.8580, 18.3852}, {36.2715, 50.5065, 21.2231}, 1.4146},   // 30
    {{90.8027, -2.0831, 1.4410}, {91.1528, -1.6435, 0.0447}, 1.4441},     // 31
    {{90.9257, -0.5406, -0.9208}, {88.6381, -0.8985, -0.7239}, 1.5381},   // 32
    {{6.7747, -0.2908, -2.4247}, {5.8714, -0.0985, -2.2286}, 0.6377},     // 33
    {{2.0776, 0.0795, -1.1350}, {0.9033, -0.0636, -0.5514}, 0.9082},      // 34
};
static_assert(std::size(kSharma) == 34);

TEST(Ciede2000, MatchesSharmaWuDalalTestData) {
    for (std::size_t i = 0; i < std::size(kSharma); ++i) {
        const auto& p = kSharma[i];
        EXPECT_NEAR(ciede2000(p.first, p.second), p.delta_e00, 1e-4) << "pair " << i + 1;
    }
}

TEST(Ciede2000, IsSymmetricOnTheTestData) {
    // Swapping the colours negates ΔL', ΔC', Δh' and ΔH' and leaves the means unchanged, so ΔE00 is
    // symmetric; the paper's discontinuity (|h1' − h2'| = 180°, pairs 9–16 lie near it) is a jump in
    // value, not an asymmetry.
    for (std::size_t i = 0; i < std::size(kSharma); ++i) {
        const auto& p = kSharma[i];
        EXPECT_NEAR(ciede2000(p.first, p.second), ciede2000(p.second, p.first), 1e-12) << "pair " << i + 1;
    }
}

TEST(Ciede2000, IsSymmetricAcrossTheHueCircle) {
    // Pairs on both sides of the 0°/360° seam and of the 180° gap between hues.
    for (double h1 = 0.0; h1 < 360.0; h1 += 13.0)
        for (double h2 = 5.0; h2 < 360.0; h2 += 29.0) {
            const double r1 = h1 * std::numbers::pi / 180.0, r2 = h2 * std::numbers::pi / 180.0;
            const Lab x{40.0, 30.0 * std::cos(r1), 30.0 * std::sin(r1)};
            const Lab y{55.0, 12.0 * std::cos(r2), 12.0 * std::sin(r2)};
            EXPECT_NEAR(ciede2000(x, y), ciede2000(y, x), 1e-12) << "h1=" << h1 << " h2=" << h2;
        }
}

TEST(Ciede2000, IsZeroForIdenticalColours) {
    for (const Lab& x : {Lab{}, Lab{50, 0, 0}, Lab{99.5, 0.005, -0.010}, Lab{42, 13, -7}, Lab{60.2574, -34.0099, 36.2677},
                         Lab{20, -80, 90}}) {
        EXPECT_EQ(ciede2000(x, x), 0.0) << x.L << " " << x.a << " " << x.b;
    }
}

TEST(Ciede2000, PureLightnessDifferences) {
    // Black to white with (nearly) no chroma: ΔE00 = ΔL / S_L = 100 at L̄ = 50 (S_L = 1).
    EXPECT_NEAR(ciede2000({100.0, 0.005, -0.010}, {0.0, 0.0, 0.0}), 100.0, 1e-4);
    // Neutrals at mean lightness 50 differ by exactly ΔL*.
    EXPECT_NEAR(ciede2000({45.0, 0.0, 0.0}, {55.0, 0.0, 0.0}), 10.0, 1e-12);
}

TEST(ColorDifference, WhiteIsLightness100) {
    for (const XYZ& white : {XYZ{0.95047, 1.0, 1.08883}, XYZ{1.0, 1.0, 1.0}, XYZ{0.96422, 1.0, 0.82521}}) {
        const Lab lab = xyz_to_lab(white, white);
        EXPECT_NEAR(lab.L, 100.0, 1e-12);
        EXPECT_NEAR(lab.a, 0.0, 1e-12);
        EXPECT_NEAR(lab.b, 0.0, 1e-12);
    }
    const Lab black = xyz_to_lab({0.0, 0.0, 0.0}, {0.95047, 1.0, 1.08883});
    EXPECT_NEAR(black.L, 0.0, 1e-12);
}

TEST(ColorDifference, MiddleGreyLightness) {
    const XYZ white{0.95047, 1.0, 1.08883};
    const XYZ grey{0.18 * white.X, 0.18 * white.Y, 0.18 * white.Z};
    EXPECT_NEAR(xyz_to_lab(grey, white).L, 49.496, 5e-4);
    // Y/Yn = 0.5 → L* = 116·∛0.5 − 16 ≈ 76.0693.
    EXPECT_NEAR(xyz_to_lab({0.0, 0.5, 0.0}, {1.0, 1.0, 1.0}).L, 76.0693, 1e-4);
}

TEST(ColorDifference, NeutralsHaveNoChroma) {
    const XYZ white{0.95047, 1.0, 1.08883};
    for (double s : {1e-5, 1e-3, 216.0 / 24389.0, 0.01, 0.18, 0.5, 0.9, 1.0, 2.0}) {
        const Lab lab = xyz_to_lab({s * white.X, s * white.Y, s * white.Z}, white);
        EXPECT_NEAR(lab.a, 0.0, 1e-12) << "s=" << s;
        EXPECT_NEAR(lab.b, 0.0, 1e-12) << "s=" << s;
    }
}

TEST(ColorDifference, LightnessIsContinuousAtTheBranchPoint) {
    const double eps = 216.0 / 24389.0;
    const XYZ white{1.0, 1.0, 1.0};
    const double below = xyz_to_lab({0.0, std::nextafter(eps, 0.0), 0.0}, white).L;
    const double at = xyz_to_lab({0.0, eps, 0.0}, white).L;
    const double above = xyz_to_lab({0.0, std::nextafter(eps, 1.0), 0.0}, white).L;
    EXPECT_NEAR(below, above, 1e-9);
    EXPECT_NEAR(at, 8.0, 1e-12);  // L* = κ ε = 8 where the branches meet
    EXPECT_NEAR(xyz_to_lab({0.0, eps * (1 - 1e-12), 0.0}, white).L,
                xyz_to_lab({0.0, eps * (1 + 1e-12), 0.0}, white).L, 1e-9);
    // Below ε the linear branch: L* = κ Y/Yn.
    EXPECT_NEAR(xyz_to_lab({0.0, 0.001, 0.0}, white).L, 24389.0 / 27.0 * 0.001, 1e-12);
}

TEST(ColorDifference, ChromaticAxesHaveTheRightSigns) {
    const XYZ white{0.95047, 1.0, 1.08883};
    // More X than the white at equal Y: reddish (a* > 0); more Z: bluish (b* < 0).
    EXPECT_GT(xyz_to_lab({0.6, 0.5, 0.5 * white.Z}, white).a, 0.0);
    EXPECT_LT(xyz_to_lab({0.5 * white.X, 0.5, 0.7}, white).b, 0.0);
}

}  // namespace
}  // namespace metalfit
