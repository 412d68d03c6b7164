// Daylight illuminants from S₀, S₁, S₂ (CIE 015:2018) against the CIE's own D65 and D50 tables, the illuminant
// names, and the CIE 2015 observers' tables (zero below 390 nm).
#include <gtest/gtest.h>

#include "test_support.hpp"

#include <algorithm>
#include <cmath>
#include <cstdio>

#include "libfit/base/errors.hpp"
#include "libfit/color/colorimetry.hpp"
#include "libfit/color/daylight.hpp"
#include "libfit/color/illuminant.hpp"

namespace metalfit {
namespace test_daylight {

using namespace metalfit::test;

const DaylightBasis& basis() {
    static const DaylightBasis b = DaylightBasis::load(kData / "cie" / "cie_daylight_basis_S0S1S2.csv");
    return b;
}

// max |computed − table| / table over the table's 1 nm points (or only its 5 nm points).
double max_relative_difference(const DenseSpectrum<double>& computed, const DenseSpectrum<double>& table, int step) {
    double worst = 0.0;
    for (int nm = table.first_nm(); nm <= table.last_nm(); nm += step)
        worst = std::max(worst, std::abs(computed.at_nm(nm) - table.at_nm(nm)) / table.at_nm(nm));
    return worst;
}

TEST(Daylight, BasisCovers300To830NmAt5Nm) {
    EXPECT_EQ(basis().first_nm, 300);
    EXPECT_EQ(basis().last_nm(), 830);
    EXPECT_EQ(basis().S.size(), 107u);
}

TEST(Daylight, TabulatedD65AndD50AreReproducedOnlyWithTheC2Correction) {
    struct Case {
        Illuminant table;
        double nominal, integer_kelvin;
    };
    for (const Case& c : {Case{Illuminant::D65, 6500.0, 6504.0}, Case{Illuminant::D50, 5000.0, 5003.0}}) {
        const DenseSpectrum<double> table = c.table.spectrum(kData);
        ASSERT_EQ(table.first_nm(), 300);
        ASSERT_EQ(table.last_nm(), 830);
        // T = nominal × 1.4388/1.4380, unrounded; M₁, M₂ to three decimals: the CIE's 6-figure rounding
        // (data/cie/SOURCES.md: 8.2e-6 for D65 and 4.9e-6 for D50 at the 5 nm points).
        const auto corrected = daylight_spectrum(basis(), daylight_coefficients(c.nominal * kDaylightC2Correction));
        const auto integer = daylight_spectrum(basis(), daylight_coefficients(c.integer_kelvin));
        const auto unrounded = daylight_spectrum(
            basis(), daylight_coefficients(c.nominal * kDaylightC2Correction, DaylightRounding::unrounded));
        // The figures of docs/colour.md.
        std::printf("%s: T = nominal x 1.4388/1.4380: max rel. difference %.2g (5 nm), %.2g (1 nm); T = %.0f K: %.2g; "
                    "M1, M2 unrounded: %.2g\n",
                    c.table.name().c_str(), max_relative_difference(corrected, table, 5),
                    max_relative_difference(corrected, table, 1), c.integer_kelvin,
                    max_relative_difference(integer, table, 5), max_relative_difference(unrounded, table, 5));
        EXPECT_LT(max_relative_difference(corrected, table, 5), 8.5e-6) << c.table.name();
        EXPECT_LT(max_relative_difference(corrected, table, 1), 9e-6) << c.table.name();
        // T rounded to whole kelvin first: M₁ (D65) or M₂ (D50) lands on the other side of a rounding boundary.
        EXPECT_GT(max_relative_difference(integer, table, 5), 9e-4) << c.table.name();
        // Unrounded M₁, M₂ with the right T are off too (by up to 4e-4).
        EXPECT_GT(max_relative_difference(unrounded, table, 5), 1e-4) << c.table.name();
    }
    // D65's miss with 6504 K is 1.4e-3 (310 nm: 3.2990 against the table's 3.2945).
    const auto d6504 = daylight_spectrum(basis(), daylight_coefficients(6504.0));
    EXPECT_NEAR(max_relative_difference(d6504, Illuminant::D65.spectrum(kData), 5), 1.4e-3, 1e-4);
}

TEST(Daylight, CoefficientsFollowCie015) {
    // D65: x_D = 0.312720 at 6503.6 K; M₁ = −0.295, M₂ = −0.689 (data/cie/SOURCES.md). 6504 K: −0.294, −0.689.
    const DaylightCoefficients d65 = daylight_coefficients(6500.0 * kDaylightC2Correction);
    EXPECT_NEAR(d65.x, 0.312720, 5e-7);
    EXPECT_NEAR(d65.y, -3.0 * d65.x * d65.x + 2.870 * d65.x - 0.275, 1e-15);
    EXPECT_EQ(d65.M1, -0.295);
    EXPECT_EQ(d65.M2, -0.689);
    EXPECT_EQ(daylight_coefficients(6504.0).M1, -0.294);
    // Above 7000 K the second x_D formula: D75 (7503.9 K) has x = 0.299 (CIE 015 Table 5: 0.29902).
    EXPECT_NEAR(daylight_coefficients(7500.0 * kDaylightC2Correction).x, 0.29902, 5e-5);
    EXPECT_THROW(daylight_coefficients(3999.0), UsageError);
    EXPECT_THROW(daylight_coefficients(25001.0), UsageError);
}

TEST(Illuminant, NamesParseToTablesOrDaylight) {
    EXPECT_EQ(Illuminant::parse("D65").kind(), Illuminant::Kind::tabulated);
    EXPECT_EQ(Illuminant::parse("D50").kind(), Illuminant::Kind::tabulated);
    EXPECT_EQ(Illuminant::parse("E").kind(), Illuminant::Kind::equal_energy);
    const Illuminant d60 = Illuminant::parse("D60");
    EXPECT_EQ(d60.kind(), Illuminant::Kind::daylight);
    EXPECT_DOUBLE_EQ(d60.kelvin(), 6000.0 * 1.4388 / 1.4380);
    EXPECT_DOUBLE_EQ(Illuminant::parse("D6500").kelvin(), 6500.0);  // kelvin as written
    for (const char* bad : {"D", "D6", "D650", "D3000", "D30000", "d65", "F2", "D65x"})
        EXPECT_THROW(Illuminant::parse(bad), UsageError) << bad;
}

TEST(Illuminant, DaylightWhitePointsMatchTheCie) {
    // CIE 015:2018 Table 5 (1931 2°): D55 (0.33242, 0.34743), D75 (0.29902, 0.31485); ACES's D60 is the daylight
    // locus at 6000 K: (0.32168, 0.33767) (Academy TB-2018-001).
    struct Case {
        const char* name;
        double x, y;
    };
    for (const Case& c :
         {Case{"D55", 0.33242, 0.34743}, Case{"D75", 0.29902, 0.31485}, Case{"D6000", 0.32168, 0.33767}}) {
        const XYZ w =
            Colorimetry::load(kData, Observer::cie1931_2deg, Illuminant::parse(c.name), Adaptation::none).white();
        EXPECT_NEAR(w.X / (w.X + w.Y + w.Z), c.x, 6e-5) << c.name;
        EXPECT_NEAR(w.Y / (w.X + w.Y + w.Z), c.y, 6e-5) << c.name;
    }
}

TEST(Cie2015Observers, ZeroBelow390NmAndTheCiesColumnSums) {
    struct Case {
        Observer observer;
        double x, y, z;  // the CIE metadata's column sums over 390–830 nm (data/cie/SOURCES.md)
    };
    for (const Case& c : {Case{Observer::cie2015_2deg, 113.042318330084, 113.0423145713364, 113.04231479170},
                          Case{Observer::cie2015_10deg, 118.518090897436, 118.5180915321789, 118.518095303296}}) {
        const DenseSpectrum<XYZ> cmf = colour_matching_functions(kData, c.observer);
        ASSERT_EQ(cmf.first_nm(), 360);
        for (int nm = 360; nm < 390; ++nm) EXPECT_EQ(cmf.at_nm(nm), XYZ{}) << nm;
        EXPECT_GT(cmf.at_nm(390).Z, 0.01);
        XYZ sum{};
        for (const XYZ& v : cmf.values()) sum += v;
        EXPECT_NEAR(sum.X, c.x, 1e-6);
        EXPECT_NEAR(sum.Y, c.y, 1e-6);
        EXPECT_NEAR(sum.Z, c.z, 1e-6);
    }
    // D65 under the 2015 2° observer: (0.313452, 0.330802), as Adobe's table prints it (0.313452449, 0.330801828).
    const XYZ w = Colorimetry::load(kData, Observer::cie2015_2deg, Illuminant::D65).white();
    EXPECT_NEAR(w.X / (w.X + w.Y + w.Z), 0.313452449, 1e-8);
    EXPECT_NEAR(w.Y / (w.X + w.Y + w.Z), 0.330801828, 1e-8);
    EXPECT_EQ(parse_observer("2015-2"), Observer::cie2015_2deg);
    EXPECT_EQ(parse_observer("2015-10"), Observer::cie2015_10deg);
    EXPECT_EQ(option_name(Observer::cie2015_10deg), "2015-10");
}

}  // namespace test_daylight
}  // namespace metalfit
