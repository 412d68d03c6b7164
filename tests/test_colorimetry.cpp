// Colorimetry: white normalisation and chromaticities against published values and table sums.
#include <gtest/gtest.h>

#include "test_support.hpp"

#include <vector>

#include "libfit/base/errors.hpp"
#include "libfit/color/colorimetry.hpp"

namespace metalfit {
namespace test_colorimetry {

using namespace metalfit::test;

struct Chromaticity {
    double x, y;
};
Chromaticity chromaticity(const XYZ& c) { return {c.X / (c.X + c.Y + c.Z), c.Y / (c.X + c.Y + c.Z)}; }

TEST(Colorimetry, PerfectReflectorHasUnitLuminanceForEveryObserverAndIlluminant) {
    for (Observer o : {Observer::cie1931_2deg, Observer::cie1964_10deg})
        for (Illuminant i : {Illuminant::D65, Illuminant::A, Illuminant::E}) {
            const Colorimetry c = Colorimetry::load(kData, o, i);
            EXPECT_NEAR(c.white().Y, 1.0, 1e-12) << to_string(o) << " " << to_string(i);
            ASSERT_EQ(c.weights().size(), 471u);
            EXPECT_EQ(c.weights().first_nm(), 360);
            EXPECT_EQ(c.weights().last_nm(), 830);
        }
}

TEST(Colorimetry, WhitePointsMatchPublishedChromaticities) {
    // CIE 15:2004 Table T.3 (1 nm data): D65 2° (0.31272, 0.32903), 10° (0.31382, 0.33100); A 2° (0.44757, 0.40745).
    const auto d65 = chromaticity(Colorimetry::load(kData, Observer::cie1931_2deg, Illuminant::D65).white());
    EXPECT_NEAR(d65.x, 0.31272, 5e-5);
    EXPECT_NEAR(d65.y, 0.32903, 5e-5);
    const auto d65_10 = chromaticity(Colorimetry::load(kData, Observer::cie1964_10deg, Illuminant::D65).white());
    EXPECT_NEAR(d65_10.x, 0.31382, 5e-5);
    EXPECT_NEAR(d65_10.y, 0.33100, 5e-5);
    const auto a = chromaticity(Colorimetry::load(kData, Observer::cie1931_2deg, Illuminant::A).illuminant_white());
    EXPECT_NEAR(a.x, 0.44757, 5e-5);
    EXPECT_NEAR(a.y, 0.40745, 5e-5);
}

TEST(Colorimetry, EqualEnergyWhiteIsTheRatioOfTheTableSums) {
    // data/cie/SOURCES.md: Σx̄, Σȳ, Σz̄ over 360–830 nm at 1 nm = 106.8655, 106.8569, 106.8923.
    const XYZ w = Colorimetry::load(kData, Observer::cie1931_2deg, Illuminant::E).illuminant_white();
    EXPECT_NEAR(w.X, 106.8655 / 106.8569, 2e-6);
    EXPECT_NEAR(w.Z, 106.8923 / 106.8569, 2e-6);
}

TEST(Colorimetry, IntegrationIsLinearInReflectance) {
    const Colorimetry c = Colorimetry::load(kData, Observer::cie1931_2deg, Illuminant::D65);
    const DenseSpectrum<double> grey(360, 830, 0.25);
    const XYZ g = c.integrate(grey);
    EXPECT_NEAR(g.X, 0.25 * c.white().X, 1e-14);
    EXPECT_NEAR(g.Y, 0.25, 1e-14);
    EXPECT_NEAR(g.Z, 0.25 * c.white().Z, 1e-14);
    // A reflectance that is 1 only above 600 nm is reddish: X/Y above the white's, Z tiny.
    const auto red = DenseSpectrum<double>::sampled(360, 830, [](int nm) { return nm >= 600 ? 1.0 : 0.0; });
    const XYZ r = c.integrate(red);
    EXPECT_GT(r.X / r.Y, c.white().X / c.white().Y);
    EXPECT_LT(r.Z, 0.01);
    // A reflectance on another grid is refused, not misaligned.
    EXPECT_THROW((void)c.integrate(DenseSpectrum<double>(361, 831, 1.0)), std::invalid_argument);
    EXPECT_THROW((void)c.integrate(DenseSpectrum<double>(360, 829, 1.0)), std::invalid_argument);
}

TEST(DenseSpectrum, GridIndexingAndMapping) {
    const auto s = DenseSpectrum<double>::sampled(400, 404, [](int nm) { return nm - 400.0; });
    EXPECT_EQ(s.size(), 5u);
    EXPECT_EQ(s.last_nm(), 404);
    EXPECT_EQ(s.at_nm(403), 3.0);
    EXPECT_EQ(s.nm(2), 402);
    EXPECT_THROW((void)s.at_nm(399), std::out_of_range);
    EXPECT_THROW((void)s.at_nm(405), std::out_of_range);
    EXPECT_THROW(DenseSpectrum<double>(500, 499), std::invalid_argument);
    const DenseSpectrum<XYZ> m = s.map([](double v) { return XYZ{v, 2 * v, 3 * v}; });
    ASSERT_TRUE(m.same_grid(s));
    EXPECT_EQ(m.at_nm(404), (XYZ{4, 8, 12}));
    // Σ a·b against the hand sum 0·0 + 1·1 + ... + 4·4 = 30.
    EXPECT_EQ(sum_of_products(s, s), 30.0);
    EXPECT_THROW((void)sum_of_products(s, DenseSpectrum<double>(400, 405)), std::invalid_argument);
}

TEST(Colorimetry, BadInputsAreNamedErrors) {
    EXPECT_THROW(Colorimetry::load("/nonexistent-metalfit-data", Observer::cie1931_2deg, Illuminant::D65), InputError);
    EXPECT_THROW(parse_observer("1976"), UsageError);
    EXPECT_THROW(parse_illuminant("F2"), UsageError);
    EXPECT_EQ(parse_observer("1964"), Observer::cie1964_10deg);
    EXPECT_EQ(parse_illuminant("A"), Illuminant::A);
}

}  // namespace test_colorimetry
}  // namespace metalfit
