// Chromatic adaptation: Bradford against Lindbloom's published matrices, CAT02 and von Kries against an
// independent Eigen computation, and the adaptation of the colorimetry against the same matrices applied by hand.
#include <gtest/gtest.h>

#include "test_support.hpp"

#include <Eigen/Dense>

#include <cstdio>

#include "libfit/base/errors.hpp"
#include "libfit/color/chromatic_adaptation.hpp"
#include "libfit/color/colorimetry.hpp"
#include "libfit/io/catalog.hpp"
#include "libfit/reference/reference_curve.hpp"

namespace metalfit {
namespace test_chromatic_adaptation {

using namespace metalfit::test;

void expect_matrix_near(const Matrix3& a, const double (&expected)[3][3], double tolerance) {
    for (int i = 0; i < 3; ++i)
        for (int j = 0; j < 3; ++j) EXPECT_NEAR(a(i, j), expected[i][j], tolerance) << "row " << i << " column " << j;
}

// Bruce Lindbloom, "Chromatic Adaptation" (brucelindbloom.com), Bradford, with his reference whites
// D65 = (0.95047, 1, 1.08883) and D50 = (0.96422, 1, 0.82521); printed to 7 decimals.
constexpr XYZ kLindbloomD65{0.95047, 1.0, 1.08883};
constexpr XYZ kLindbloomD50{0.96422, 1.0, 0.82521};
constexpr double kBradfordD65toD50[3][3] = {
    {1.0478112, 0.0228866, -0.0501270}, {0.0295424, 0.9904844, -0.0170491}, {-0.0092345, 0.0150436, 0.7521316}};
constexpr double kBradfordD50toD65[3][3] = {
    {0.9555766, -0.0230393, 0.0631636}, {-0.0282895, 1.0099416, 0.0210077}, {0.0122982, -0.0204830, 1.3299098}};

TEST(ChromaticAdaptation, BradfordMatchesLindbloomsPublishedMatrices) {
    expect_matrix_near(adaptation_matrix(Adaptation::bradford, kLindbloomD65, kLindbloomD50), kBradfordD65toD50, 6e-8);
    expect_matrix_near(adaptation_matrix(Adaptation::bradford, kLindbloomD50, kLindbloomD65), kBradfordD50toD65, 6e-8);
}

// The same transform computed with Eigen: M = C⁻¹ diag(C·t ./ C·s) C.
Eigen::Matrix3d independent(const Eigen::Matrix3d& cone, const XYZ& s, const XYZ& t) {
    const Eigen::Vector3d cs = cone * Eigen::Vector3d(s.X, s.Y, s.Z), ct = cone * Eigen::Vector3d(t.X, t.Y, t.Z);
    return cone.inverse() * ct.cwiseQuotient(cs).asDiagonal() * cone;
}

TEST(ChromaticAdaptation, EveryMethodAgreesWithAnIndependentComputationAndMapsWhiteToWhite) {
    Eigen::Matrix3d bradford, cat02;
    bradford << 0.8951, 0.2664, -0.1614, -0.7502, 1.7135, 0.0367, 0.0389, -0.0685, 1.0296;
    // CIE 159:2004 (CIECAM02), M_CAT02.
    cat02 << 0.7328, 0.4296, -0.1624, -0.7036, 1.6975, 0.0061, 0.0030, 0.0136, 0.9834;
    const XYZ a = xyz_from_chromaticity(0.44757, 0.40745), d65 = xyz_from_chromaticity(0.3127, 0.3290);
    const std::pair<Adaptation, Eigen::Matrix3d> methods[] = {{Adaptation::bradford, bradford},
                                                              {Adaptation::cat02, cat02},
                                                              {Adaptation::von_kries_xyz, Eigen::Matrix3d::Identity()}};
    for (const auto& [method, cone] : methods) {
        const Matrix3 m = adaptation_matrix(method, a, d65);
        const Eigen::Matrix3d e = independent(cone, a, d65);
        for (int i = 0; i < 3; ++i)
            for (int j = 0; j < 3; ++j) EXPECT_NEAR(m(i, j), e(i, j), 1e-13) << to_string(method);
        const XYZ w = m * a;
        EXPECT_NEAR(w.X, d65.X, 1e-14) << to_string(method);
        EXPECT_NEAR(w.Y, d65.Y, 1e-14) << to_string(method);
        EXPECT_NEAR(w.Z, d65.Z, 1e-14) << to_string(method);
    }
    // The methods differ off the white: a saturated colour lands in different places.
    const XYZ red{0.4, 0.2, 0.02};
    const XYZ b = adaptation_matrix(Adaptation::bradford, a, d65) * red,
              c = adaptation_matrix(Adaptation::cat02, a, d65) * red;
    EXPECT_GT(std::abs(b.Z - c.Z) + std::abs(b.X - c.X), 1e-4);
}

TEST(ChromaticAdaptation, EqualWhitesAndNoneAreExactlyTheIdentity) {
    EXPECT_EQ(adaptation_matrix(Adaptation::bradford, kLindbloomD65, kLindbloomD65), Matrix3::identity());
    EXPECT_EQ(adaptation_matrix(Adaptation::none, kLindbloomD65, kLindbloomD50), Matrix3::identity());
    // The product form alone would not be exactly the identity: that is why equal whites are not multiplied out.
    const Matrix3 c = cone_matrix(Adaptation::bradford);
    EXPECT_NE(inverse(c) * c, Matrix3::identity());
    const Matrix3 round_trip = inverse(c) * c;
    for (int i = 0; i < 3; ++i)
        for (int j = 0; j < 3; ++j) EXPECT_NEAR(round_trip(i, j), i == j ? 1.0 : 0.0, 1e-15);
}

TEST(ChromaticAdaptation, NamesParseAndPrint) {
    for (Adaptation a : {Adaptation::bradford, Adaptation::cat02, Adaptation::von_kries_xyz, Adaptation::none})
        EXPECT_EQ(parse_adaptation(to_string(a)), a);
    EXPECT_THROW(parse_adaptation("vonkries"), UsageError);
}

TEST(ColorimetryAdaptation, AdaptedWeightsAreTheMatrixTimesTheUnadaptedOnes) {
    for (Observer o : {Observer::cie1931_2deg, Observer::cie2015_2deg})
        for (const Illuminant& i : {Illuminant::A, Illuminant::D50, Illuminant::parse("D60"), Illuminant::E}) {
            const Colorimetry plain = Colorimetry::load(kData, o, i, Adaptation::none);
            const XYZ d65 = Colorimetry::load(kData, o, Illuminant::D65, Adaptation::none).white();
            for (Adaptation a : {Adaptation::bradford, Adaptation::cat02, Adaptation::von_kries_xyz}) {
                const Colorimetry adapted = Colorimetry::load(kData, o, i, a);
                ASSERT_TRUE(adapted.adapted()) << to_string(i);
                // The adapted white is D65's white under the same observer (the connection white).
                EXPECT_NEAR(adapted.white().X, d65.X, 1e-12)
                    << to_string(o) << " " << to_string(i) << " " << to_string(a);
                EXPECT_NEAR(adapted.white().Y, 1.0, 1e-12);
                EXPECT_NEAR(adapted.white().Z, d65.Z, 1e-12);
                // Every weight is M · the unadapted weight, M computed independently from the two whites.
                Eigen::Matrix3d cone = Eigen::Matrix3d::Identity();
                const Matrix3 c = cone_matrix(a);
                for (int r = 0; r < 3; ++r)
                    for (int k = 0; k < 3; ++k) cone(r, k) = c(r, k);
                const Eigen::Matrix3d m = independent(cone, plain.white(), d65);
                for (int nm : {400, 550, 700}) {
                    const XYZ w = plain.weights().at_nm(nm), v = adapted.weights().at_nm(nm);
                    const Eigen::Vector3d e = m * Eigen::Vector3d(w.X, w.Y, w.Z);
                    EXPECT_NEAR(v.X, e(0), 1e-15);
                    EXPECT_NEAR(v.Y, e(1), 1e-15);
                    EXPECT_NEAR(v.Z, e(2), 1e-15);
                }
            }
        }
}

TEST(ColorimetryAdaptation, D65IsNotAdaptedAndKeepsItsWeightsBitForBit) {
    for (Observer o :
         {Observer::cie1931_2deg, Observer::cie1964_10deg, Observer::cie2015_2deg, Observer::cie2015_10deg}) {
        const Colorimetry none = Colorimetry::load(kData, o, Illuminant::D65, Adaptation::none);
        for (Adaptation a : {Adaptation::bradford, Adaptation::cat02, Adaptation::von_kries_xyz}) {
            const Colorimetry c = Colorimetry::load(kData, o, Illuminant::D65, a);
            EXPECT_FALSE(c.adapted());
            EXPECT_EQ(c.adaptation_matrix(), Matrix3::identity());
            ASSERT_EQ(c.weights().size(), none.weights().size());
            for (std::size_t k = 0; k < c.weights().size(); ++k) ASSERT_EQ(c.weights()[k], none.weights()[k]);
            EXPECT_EQ(c.white(), none.white());
        }
    }
}

TEST(ColorimetryAdaptation, GoldUnderAAgreesWithBradfordToTheNominalD65White) {
    // An independent route: XYZ under A unadapted, Bradford (Eigen) to the RGB spaces' nominal white (0.3127, 0.3290),
    // OCIO, divided by the same route's white. metalfit adapts to D65's computed white and white-balances; the two
    // differ only by what the white balance leaves.
    const OcioConfigChoice shipped{kData / "ocio" / "config.ocio", "test"};
    const ColorSpaceConverter rec709 = ColorSpaceConverter::create(shipped);
    const Material gold = load_material(Catalog::load(kData), "Au");
    const RGB metalfit =
        ReferenceCurve(gold, Colorimetry::load(kData, Observer::cie1931_2deg, Illuminant::A), rec709)(1.0);
    const Colorimetry plain = Colorimetry::load(kData, Observer::cie1931_2deg, Illuminant::A, Adaptation::none);
    const XYZ f0 = ReferenceCurve(gold, plain, rec709).xyz(1.0);
    Eigen::Matrix3d bradford;
    bradford << 0.8951, 0.2664, -0.1614, -0.7502, 1.7135, 0.0367, 0.0389, -0.0685, 1.0296;
    const Eigen::Matrix3d m = independent(bradford, plain.white(), xyz_from_chromaticity(0.3127, 0.3290));
    const auto adapt = [&](const XYZ& v) {
        const Eigen::Vector3d e = m * Eigen::Vector3d(v.X, v.Y, v.Z);
        return XYZ{e(0), e(1), e(2)};
    };
    const RGB nominal = rec709(adapt(f0)) / rec709(adapt(plain.white()));
    double worst = 0.0;
    for (int c = 0; c < 3; ++c) worst = std::max(worst, std::abs(metalfit[c] - nominal[c]));
    std::printf(
        "gold under A: metalfit F0 (%.6f, %.6f, %.6f), Bradford to (0.3127, 0.3290): (%.6f, %.6f, %.6f), worst %.2g\n",
        metalfit.r, metalfit.g, metalfit.b, nominal.r, nominal.g, nominal.b, worst);
    EXPECT_LT(worst, 1e-4);
    EXPECT_NEAR(metalfit.b, 0.357, 5e-4);  // the figure; 0.200 without adaptation
}

}  // namespace test_chromatic_adaptation
}  // namespace metalfit
