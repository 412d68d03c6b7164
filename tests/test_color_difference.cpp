// CIE L*a*b* and CIEDE2000: Sharma, Wu and Dalal's published test data, symmetry, and the
// L*a*b* anchors (white, 18 % grey, neutrals, the ε branch point).
#include <gtest/gtest.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdio>
#include <limits>
#include <numbers>
#include <random>

#include "libfit/color/color_difference.hpp"

namespace metalfit {
namespace test_color_difference {

struct SharmaPair {
    Lab first, second;
    double delta_e00;
};

// G. Sharma, W. Wu, E. N. Dalal, "The CIEDE2000 color-difference formula: implementation notes,
// supplementary test data, and mathematical observations", Color Res. Appl. 30(1), 2005, Table 1.
// Pairs 1–6: true chroma / hue differences; 7–16: arctangent and mean-hue edge cases (neutrals,
// hues straddling 0°/180°); 17–20: large differences; 21–34: CIE technical report pairs.
constexpr SharmaPair kSharma[] = {
    {{50.0000, 2.6772, -79.7751}, {50.0000, 0.0000, -82.7485}, 2.0425},    // 1
    {{50.0000, 3.1571, -77.2803}, {50.0000, 0.0000, -82.7485}, 2.8615},    // 2
    {{50.0000, 2.8361, -74.0200}, {50.0000, 0.0000, -82.7485}, 3.4412},    // 3
    {{50.0000, -1.3802, -84.2814}, {50.0000, 0.0000, -82.7485}, 1.0000},   // 4
    {{50.0000, -1.1848, -84.8006}, {50.0000, 0.0000, -82.7485}, 1.0000},   // 5
    {{50.0000, -0.9009, -85.5211}, {50.0000, 0.0000, -82.7485}, 1.0000},   // 6
    {{50.0000, 0.0000, 0.0000}, {50.0000, -1.0000, 2.0000}, 2.3669},       // 7
    {{50.0000, -1.0000, 2.0000}, {50.0000, 0.0000, 0.0000}, 2.3669},       // 8
    {{50.0000, 2.4900, -0.0010}, {50.0000, -2.4900, 0.0009}, 7.1792},      // 9
    {{50.0000, 2.4900, -0.0010}, {50.0000, -2.4900, 0.0010}, 7.1792},      // 10
    {{50.0000, 2.4900, -0.0010}, {50.0000, -2.4900, 0.0011}, 7.2195},      // 11
    {{50.0000, 2.4900, -0.0010}, {50.0000, -2.4900, 0.0012}, 7.2195},      // 12
    {{50.0000, -0.0010, 2.4900}, {50.0000, 0.0009, -2.4900}, 4.8045},      // 13
    {{50.0000, -0.0010, 2.4900}, {50.0000, 0.0010, -2.4900}, 4.8045},      // 14
    {{50.0000, -0.0010, 2.4900}, {50.0000, 0.0011, -2.4900}, 4.7461},      // 15
    {{50.0000, 2.5000, 0.0000}, {50.0000, 0.0000, -2.5000}, 4.3065},       // 16
    {{50.0000, 2.5000, 0.0000}, {73.0000, 25.0000, -18.0000}, 27.1492},    // 17
    {{50.0000, 2.5000, 0.0000}, {61.0000, -5.0000, 29.0000}, 22.8977},     // 18
    {{50.0000, 2.5000, 0.0000}, {56.0000, -27.0000, -3.0000}, 31.9030},    // 19
    {{50.0000, 2.5000, 0.0000}, {58.0000, 24.0000, 15.0000}, 19.4535},     // 20
    {{50.0000, 2.5000, 0.0000}, {50.0000, 3.1736, 0.5854}, 1.0000},        // 21
    {{50.0000, 2.5000, 0.0000}, {50.0000, 3.2972, 0.0000}, 1.0000},        // 22
    {{50.0000, 2.5000, 0.0000}, {50.0000, 1.8634, 0.5757}, 1.0000},        // 23
    {{50.0000, 2.5000, 0.0000}, {50.0000, 3.2592, 0.3350}, 1.0000},        // 24
    {{60.2574, -34.0099, 36.2677}, {60.4626, -34.1751, 39.4387}, 1.2644},  // 25
    {{63.0109, -31.0961, -5.8663}, {62.8187, -29.7946, -4.0864}, 1.2630},  // 26
    {{61.2901, 3.7196, -5.3901}, {61.4292, 2.2480, -4.9620}, 1.8731},      // 27
    {{35.0831, -44.1164, 3.7933}, {35.0232, -40.0716, 1.5901}, 1.8645},    // 28
    {{22.7233, 20.0904, -46.6940}, {23.0331, 14.9730, -42.5619}, 2.0373},  // 29
    {{36.4612, 47.8580, 18.3852}, {36.2715, 50.5065, 21.2231}, 1.4146},    // 30
    {{90.8027, -2.0831, 1.4410}, {91.1528, -1.6435, 0.0447}, 1.4441},      // 31
    {{90.9257, -0.5406, -0.9208}, {88.6381, -0.8985, -0.7239}, 1.5381},    // 32
    {{6.7747, -0.2908, -2.4247}, {5.8714, -0.0985, -2.2286}, 0.6377},      // 33
    {{2.0776, 0.0795, -1.1350}, {0.9033, -0.0636, -0.5514}, 0.9082},       // 34
};
static_assert(std::size(kSharma) == 34);

TEST(Ciede2000, MatchesSharmaWuDalalTestData) {
    for (std::size_t i = 0; i < std::size(kSharma); ++i) {
        const auto& p = kSharma[i];
        EXPECT_NEAR(ciede2000(p.first, p.second), p.delta_e00, 1e-4) << "pair " << i + 1;
    }
}

// ---- the textbook form, the independent check of ciede2000's shorter one ----

// Sharma, Wu and Dalal's eqs. 1–21 step by step with the hue angles in degrees (atan2, two hypots each side, the four
// cosines of T): what color_difference.cpp computed before it took the hue terms from the (a', b) vectors. In
// double it is the form the records were written with; in long double (64-bit significand on x86-64) it is the
// exact value to ~1e-18 wherever the formula is continuous.
// edge, where given, receives the pair's distance in degrees from the formula's jumps: hues 180° apart (T and the
// mean hue jump) and the mean hue at 0°/360° (the rotation term jumps).
template <class T>
T textbook_ciede2000(const Lab& first, const Lab& second, T* edge = nullptr) {
    using std::abs, std::atan2, std::cos, std::exp, std::hypot, std::sin, std::sqrt;
    const T degree = std::numbers::pi_v<T> / 180;
    const T L1 = first.L, a1 = first.a, b1 = first.b, L2 = second.L, a2 = second.a, b2 = second.b;
    const auto pow7 = [](T x) { return x * x * x * x * x * x * x; };
    const auto hue = [&](T b, T a) -> T {
        if (a == 0 && b == 0) return 0;
        const T h = atan2(b, a) / degree;
        return h < 0 ? h + 360 : h;
    };
    const T k25_7 = 6103515625.0L;
    const T C1 = hypot(a1, b1), C2 = hypot(a2, b2);
    const T C_mean7 = pow7((C1 + C2) / 2);
    const T G = (1 - sqrt(C_mean7 / (C_mean7 + k25_7))) / 2;
    const T a1p = (1 + G) * a1, a2p = (1 + G) * a2;
    const T C1p = hypot(a1p, b1), C2p = hypot(a2p, b2);
    const T h1p = hue(b1, a1p), h2p = hue(b2, a2p);
    const T dLp = L2 - L1, dCp = C2p - C1p, C_product = C1p * C2p;
    T dhp = 0;
    if (C_product != 0) {
        dhp = h2p - h1p;
        if (dhp > 180)
            dhp -= 360;
        else if (dhp < -180)
            dhp += 360;
    }
    const T dHp = 2 * sqrt(C_product) * sin(dhp / 2 * degree);
    const T L_mean = (L1 + L2) / 2, Cp_mean = (C1p + C2p) / 2;
    T hp_mean = h1p + h2p;
    if (C_product != 0) {
        if (abs(h1p - h2p) <= 180)
            hp_mean = (h1p + h2p) / 2;
        else if (h1p + h2p < 360)
            hp_mean = (h1p + h2p + 360) / 2;
        else
            hp_mean = (h1p + h2p - 360) / 2;
    }
    if (edge) *edge = C_product == 0 ? T(360) : std::min({abs(abs(h1p - h2p) - 180), hp_mean, 360 - hp_mean});
    const T T_ = 1 - T(0.17) * cos((hp_mean - 30) * degree) + T(0.24) * cos(2 * hp_mean * degree) +
                 T(0.32) * cos((3 * hp_mean + 6) * degree) - T(0.20) * cos((4 * hp_mean - 63) * degree);
    const T offset = (hp_mean - 275) / 25;
    const T d_theta = 30 * exp(-offset * offset);
    const T Cp_mean7 = pow7(Cp_mean);
    const T R_C = 2 * sqrt(Cp_mean7 / (Cp_mean7 + k25_7));
    const T L_offset2 = (L_mean - 50) * (L_mean - 50);
    const T S_L = 1 + T(0.015) * L_offset2 / sqrt(20 + L_offset2);
    const T S_C = 1 + T(0.045) * Cp_mean, S_H = 1 + T(0.015) * Cp_mean * T_;
    const T R_T = -sin(2 * d_theta * degree) * R_C;
    const T l = dLp / S_L, c = dCp / S_C, h = dHp / S_H;
    return sqrt(l * l + c * c + h * h + R_T * c * h);
}

Lab lab_at(double L, double chroma, double hue_degrees) {
    const double r = hue_degrees * std::numbers::pi / 180.0;
    return {L, chroma * std::cos(r), chroma * std::sin(r)};
}

// The rounding error of either double form: the hue angles (360°·2^-53 each) and C1', C2' carry errors of order
// 2^-53·C', so ΔE00 is known to ~2^-53·(L̄ + C̄') absolute, whatever its size: this absolute allowance (with a factor
// 8) is added to the relative 1e-12, for differences small next to the colours (the textbook form in double uses up
// to a quarter of it against the exact value).
double rounding_allowance(const Lab& x, const Lab& y) {
    const double chroma = std::hypot(x.a, x.b) + std::hypot(y.a, y.b);
    return 8.0 * std::numeric_limits<double>::epsilon() * (1.0 + chroma + 0.5 * (x.L + y.L));
}

TEST(Ciede2000, AgreesWithTheTextbookFormOnADenseRandomSet) {
    // Pairs as the metrics meet them (a colour and a close one: ΔE from 1e-4 to 10) and far apart, over neutral,
    // moderate and saturated chromas and every hue; the textbook form in double and the exact value (long double).
    std::mt19937_64 random(2000);
    std::uniform_real_distribution<double> unit(0.0, 1.0);
    double worst_relative = 0.0, worst_exact = 0.0, worst_textbook_exact = 0.0;
    int compared = 0, within_relative = 0;
    for (int i = 0; i < 400'000; ++i) {
        const double chroma_scale = std::array{0.5, 5.0, 40.0, 130.0}[i % 4];
        const Lab x = lab_at(100.0 * unit(random), chroma_scale * unit(random), 360.0 * unit(random));
        Lab y;
        if (i % 5 == 4) {
            y = lab_at(100.0 * unit(random), chroma_scale * unit(random), 360.0 * unit(random));
        } else {
            const double step = std::pow(10.0, -4.0 + 5.0 * unit(random));
            y = {x.L + step * (2.0 * unit(random) - 1.0), x.a + step * (2.0 * unit(random) - 1.0),
                 x.b + step * (2.0 * unit(random) - 1.0)};
        }
        const double got = ciede2000(x, y);
        const double book = textbook_ciede2000<double>(x, y);
        long double edge = 0;
        const long double exact = textbook_ciede2000<long double>(x, y, &edge);
        // At the formula's own jumps the two forms' roundings can fall on either side: pairs within 1e-7° of them are
        // the edge-case tests' business (below).
        if (edge < 1e-7L) continue;
        const double allowance = rounding_allowance(x, y);
        const double difference = std::abs(got - book);
        ASSERT_LE(difference, 1e-12 * book + allowance) << i << ": " << got << " against " << book;
        worst_relative = std::max(worst_relative, difference / book);
        within_relative += difference <= 1e-12 * book;
        ASSERT_LE(std::abs(got - exact), 1e-13L * exact + allowance)
            << i << ": " << got << " against " << double(exact);
        worst_exact = std::max(worst_exact, double(std::abs(got - exact) / (1e-12L * exact + allowance)));
        worst_textbook_exact =
            std::max(worst_textbook_exact, double(std::abs(book - exact) / (1e-12L * exact + allowance)));
        ++compared;
    }
    std::printf("ciede2000 against the textbook form: %d pairs, %d within 1e-12 relative, largest relative %.3g; "
                "against the exact value: %.3g (new), %.3g (textbook) of the allowance\n",
                compared, within_relative, worst_relative, worst_exact, worst_textbook_exact);
    EXPECT_GT(compared, 399'000);
}

// Within tolerance of the textbook form in double (relative 1e-12, or the rounding allowance).
::testing::AssertionResult near_textbook(const Lab& x, const Lab& y) {
    const double got = ciede2000(x, y), book = textbook_ciede2000<double>(x, y);
    if (std::abs(got - book) <= 1e-12 * book + rounding_allowance(x, y)) return ::testing::AssertionSuccess();
    return ::testing::AssertionFailure() << "(" << x.L << ", " << x.a << ", " << x.b << ") (" << y.L << ", " << y.a
                                         << ", " << y.b << "): " << got << " against the textbook's " << book;
}

// At a jump of the formula: one of its one-sided values (those of the pair with y's hue turned by ±1e-9°, exact).
::testing::AssertionResult one_of_the_sides(const Lab& x, const Lab& y) {
    const double got = ciede2000(x, y);
    const double chroma = std::hypot(y.a, y.b), hue = std::atan2(y.b, y.a) * 180.0 / std::numbers::pi;
    for (const double turn : {-1e-9, 1e-9}) {
        const long double side = textbook_ciede2000<long double>(x, lab_at(y.L, chroma, hue + turn));
        if (std::abs(got - side) <= 1e-9L * side) return ::testing::AssertionSuccess();
    }
    return ::testing::AssertionFailure() << "(" << x.L << ", " << x.a << ", " << x.b << ") (" << y.L << ", " << y.a
                                         << ", " << y.b << "): " << got << " is neither side's value";
}

TEST(Ciede2000, EdgeCasesOfSharmaWuDalal) {
    // C1'·C2' = 0: Δh' = 0 and the mean hue is the other colour's (h' = 0 for a neutral), also with both neutral.
    for (double hue = 0.0; hue < 360.0; hue += 7.5)
        for (double chroma : {1e-6, 0.01, 2.0, 30.0, 120.0}) {
            EXPECT_TRUE(near_textbook({50.0, 0.0, 0.0}, lab_at(55.0, chroma, hue)));
            EXPECT_TRUE(near_textbook(lab_at(20.0, chroma, hue), {21.0, 0.0, 0.0}));
        }
    EXPECT_TRUE(near_textbook({50.0, 0.0, 0.0}, {60.0, 0.0, 0.0}));
    EXPECT_TRUE(near_textbook({0.0, 0.0, 0.0}, {0.0, 0.0, 0.0}));
    // Hues exactly opposite ((a, b) and −s·(a, b), s a power of 2: a2' = −s·a1' exactly): |Δh'| = 180°, where T and the
    // mean hue jump; the value is one of the two sides'. Close to it the formula is continuous again.
    for (double hue = 0.0; hue < 360.0; hue += 11.0)
        for (double s : {0.5, 1.0, 4.0}) {
            const Lab x = lab_at(40.0, 20.0, hue);
            EXPECT_TRUE(one_of_the_sides(x, {45.0, -s * x.a, -s * x.b}));
            for (double off : {-1e-5, 1e-5, -0.5, 0.5})
                EXPECT_TRUE(near_textbook(x, lab_at(45.0, 20.0 * s, hue + 180.0 + off)));
        }
    // The mean hue at the 0°/360° seam: hues mirrored about 0° (b2 = −b1 exactly) have their mean at 0° itself,
    // where the rotation term jumps (exp(−(85/25)²) at 360°, nothing at 0°); around it the textbook's own values.
    for (double half : {0.5, 5.0, 30.0, 80.0}) {
        const Lab x = lab_at(60.0, 25.0, half);
        EXPECT_TRUE(one_of_the_sides(x, {62.0, x.a, -x.b}));
        for (double off : {-1e-4, 1e-4, -0.1, 0.1}) EXPECT_TRUE(near_textbook(x, lab_at(62.0, 25.0, -half + off)));
    }
    // |Δh'| = 90° exactly (dot = 0: where the mean hue is taken from the chord instead of the sum) and around it.
    for (double hue = 0.0; hue < 360.0; hue += 15.0)
        for (double off : {0.0, -1e-9, 1e-9, -1e-3, 1e-3}) {
            EXPECT_TRUE(near_textbook(lab_at(50.0, 10.0, hue), lab_at(52.0, 12.0, hue + 90.0 + off)));
            EXPECT_TRUE(near_textbook(lab_at(50.0, 10.0, hue), lab_at(52.0, 12.0, hue - 90.0 + off)));
        }
    EXPECT_TRUE(near_textbook({50.0, 10.0, 0.0}, {50.0, 0.0, 12.0}));
    // Where the rotation term is left out (mean hue up to 116.9°) and just beyond, and where it is largest (275°).
    for (double mean = 100.0; mean <= 130.0; mean += 0.25)
        for (double half : {0.01, 3.0})
            EXPECT_TRUE(near_textbook(lab_at(50.0, 30.0, mean - half), lab_at(50.0, 33.0, mean + half)));
    for (double half : {0.01, 3.0, 40.0})
        EXPECT_TRUE(near_textbook(lab_at(50.0, 30.0, 275.0 - half), lab_at(55.0, 33.0, 275.0 + half)));
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
    for (const Lab& x : {Lab{}, Lab{50, 0, 0}, Lab{99.5, 0.005, -0.010}, Lab{42, 13, -7},
                         Lab{60.2574, -34.0099, 36.2677}, Lab{20, -80, 90}}) {
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
    EXPECT_NEAR(xyz_to_lab({0.0, eps * (1 - 1e-12), 0.0}, white).L, xyz_to_lab({0.0, eps * (1 + 1e-12), 0.0}, white).L,
                1e-9);
    // Below ε the linear branch: L* = κ Y/Yn.
    EXPECT_NEAR(xyz_to_lab({0.0, 0.001, 0.0}, white).L, 24389.0 / 27.0 * 0.001, 1e-12);
}

TEST(ColorDifference, ChromaticAxesHaveTheRightSigns) {
    const XYZ white{0.95047, 1.0, 1.08883};
    // More X than the white at equal Y: reddish (a* > 0); more Z: bluish (b* < 0).
    EXPECT_GT(xyz_to_lab({0.6, 0.5, 0.5 * white.Z}, white).a, 0.0);
    EXPECT_LT(xyz_to_lab({0.5 * white.X, 0.5, 0.7}, white).b, 0.0);
}

}  // namespace test_color_difference
}  // namespace metalfit
