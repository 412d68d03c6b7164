// The shipped OCIO config through OCIO's own API: every colour space round-trips known values against forms computed
// here independently of OCIO (the IEC 61966-2-1 sRGB curve, pure powers, the ACEScct curve of ACES S-2016-001, RGB →
// XYZ matrices from the primaries and whites, the Bradford adaptation), and every MaterialX 1.39 colour-space name
// resolves to the space it means.
#include <gtest/gtest.h>

#include "test_support.hpp"

#include <OpenColorIO/OpenColorIO.h>

#include <Eigen/Dense>

#include <array>
#include <cmath>
#include <functional>
#include <map>
#include <string>

namespace metalfit {
namespace test_ocio_config {

namespace OCIO = OCIO_NAMESPACE;
using namespace metalfit::test;

using Vec = Eigen::Vector3d;
using Mat = Eigen::Matrix3d;

Vec xyz_of(double x, double y) { return {x / y, 1.0, (1.0 - x - y) / y}; }

// RGB → XYZ from the primaries and the white (SMPTE RP 177).
Mat rgb_to_xyz(const std::array<std::array<double, 2>, 3>& p, std::array<double, 2> white) {
    Mat m;
    for (int c = 0; c < 3; ++c) m.col(c) = xyz_of(p[c][0], p[c][1]);
    const Vec s = m.colPivHouseholderQr().solve(xyz_of(white[0], white[1]));
    return m * s.asDiagonal();
}

// The von Kries adaptation in the Bradford cone space from white `from` to white `to`.
Mat bradford(std::array<double, 2> from, std::array<double, 2> to) {
    Mat b;
    b << 0.8951, 0.2664, -0.1614, -0.7502, 1.7135, 0.0367, 0.0389, -0.0685, 1.0296;
    const Vec s = b * xyz_of(from[0], from[1]), d = b * xyz_of(to[0], to[1]);
    return b.inverse() * d.cwiseQuotient(s).asDiagonal() * b;
}

constexpr std::array<double, 2> kD65{0.3127, 0.3290};
constexpr std::array<double, 2> kAcesWhite{0.32168, 0.33767};
const Mat kRec709 = rgb_to_xyz({{{0.64, 0.33}, {0.30, 0.60}, {0.15, 0.06}}}, kD65);
const Mat kP3 = rgb_to_xyz({{{0.680, 0.320}, {0.265, 0.690}, {0.150, 0.060}}}, kD65);
const Mat kRec2020 = rgb_to_xyz({{{0.708, 0.292}, {0.170, 0.797}, {0.131, 0.046}}}, kD65);
const Mat kAdobeRgb = rgb_to_xyz({{{0.64, 0.33}, {0.21, 0.71}, {0.15, 0.06}}}, kD65);
// AP0 and AP1 with the ACES white, seen from D65 XYZ through the Bradford adaptation (what the _BFD builtins do).
const Mat kAp0 =
    bradford(kAcesWhite, kD65) * rgb_to_xyz({{{0.7347, 0.2653}, {0.0, 1.0}, {0.0001, -0.0770}}}, kAcesWhite);
const Mat kAp1 =
    bradford(kAcesWhite, kD65) * rgb_to_xyz({{{0.713, 0.293}, {0.165, 0.830}, {0.128, 0.044}}}, kAcesWhite);

// IEC 61966-2-1 encoding (linear → sRGB-encoded).
double srgb_encode(double v) { return v <= 0.0031308 ? 12.92 * v : 1.055 * std::pow(v, 1.0 / 2.4) - 0.055; }
// ACES S-2016-001 (ACEScct).
double acescct_encode(double v) {
    return v <= 0.0078125 ? 10.5402377416545 * v + 0.0729055341958355 : (std::log2(v) + 9.72) / 17.52;
}

using Curve = std::function<double(double)>;
const Curve kLinear = [](double v) { return v; };
Curve power(double gamma) {
    return [gamma](double v) { return std::pow(v, 1.0 / gamma); };
}

// Every colour space of the config: its RGB → XYZ-D65 matrix and its encoding of linear values.
struct Expected {
    Mat to_xyz;
    Curve encode;
};
const std::map<std::string, Expected>& expected_spaces() {
    static const std::map<std::string, Expected> spaces{
        {"CIE-XYZ-D65", {Mat::Identity(), kLinear}},
        {"sRGB - Display", {kRec709, srgb_encode}},
        {"ACES2065-1", {kAp0, kLinear}},
        {"ACEScg", {kAp1, kLinear}},
        {"ACEScct", {kAp1, acescct_encode}},
        {"Linear Rec.709 (sRGB)", {kRec709, kLinear}},
        {"Linear P3-D65", {kP3, kLinear}},
        {"Linear Rec.2020", {kRec2020, kLinear}},
        {"Linear AdobeRGB", {kAdobeRgb, kLinear}},
        {"sRGB - Texture", {kRec709, srgb_encode}},
        {"Gamma 2.2 Rec.709", {kRec709, power(2.2)}},
        {"Gamma 1.8 Rec.709", {kRec709, power(1.8)}},
        {"Gamma 2.4 Rec.709", {kRec709, power(2.4)}},
        {"Gamma 2.2 AP1", {kAp1, power(2.2)}},
        {"sRGB Encoded P3-D65", {kP3, srgb_encode}},
        {"AdobeRGB", {kAdobeRgb, power(563.0 / 256.0)}},
    };
    return spaces;
}

OCIO::ConstConfigRcPtr shipped() {
    static const OCIO::ConstConfigRcPtr config =
        OCIO::Config::CreateFromFile((kData / "ocio" / "config.ocio").string().c_str());
    return config;
}

Vec apply(const OCIO::ConstConfigRcPtr& config, const std::string& from, const std::string& to, const Vec& v) {
    const auto cpu = config->getProcessor(from.c_str(), to.c_str())->getDefaultCPUProcessor();
    float rgb[3] = {static_cast<float>(v[0]), static_cast<float>(v[1]), static_cast<float>(v[2])};
    cpu->applyRGB(rgb);
    return {rgb[0], rgb[1], rgb[2]};
}

// Linear Rec.709 values in [0, 1] (encoded spaces are defined there), each channel distinct, plus mid grey.
const std::array<Vec, 6> kLinearRec709{Vec(0.5, 0.5, 0.5), Vec(0.18, 0.02, 0.9),  Vec(0.002, 0.25, 0.05),
                                       Vec(0.8, 0.6, 0.4), Vec(0.05, 0.05, 0.05), Vec(0.35, 0.7, 0.2)};

TEST(ShippedOcioConfig, PassesOcioValidation) {
    EXPECT_NO_THROW(shipped()->validate());
    EXPECT_STREQ(shipped()->getColorSpace("scene_linear")->getName(), "Linear Rec.709 (sRGB)");
}

TEST(ShippedOcioConfig, EverySpaceIsCheckedHere) {
    const auto config = shipped();
    int colour_spaces = 0;
    for (int i = 0; i < config->getNumColorSpaces(); ++i) {
        const std::string name = config->getColorSpaceNameByIndex(i);
        if (config->getColorSpace(name.c_str())->isData()) continue;
        ++colour_spaces;
        EXPECT_TRUE(expected_spaces().count(name)) << name << " has no independent form in this test";
    }
    EXPECT_EQ(colour_spaces, static_cast<int>(expected_spaces().size()));
}

TEST(ShippedOcioConfig, EverySpaceRoundTripsKnownValuesAgainstItsCurveAndPrimaries) {
    const auto config = shipped();
    const std::string source = "Linear Rec.709 (sRGB)";
    for (const auto& [name, expected] : expected_spaces()) {
        for (const Vec& linear : kLinearRec709) {
            const Vec in_space = expected.to_xyz.inverse() * (kRec709 * linear);
            ASSERT_TRUE(in_space.minCoeff() >= 0.0) << name;  // the values stay where every curve is defined
            const Vec want = in_space.unaryExpr(expected.encode);
            const Vec got = apply(config, source, name, linear);
            EXPECT_LT((got - want).cwiseAbs().maxCoeff(), 2e-5)
                << source << " → " << name << " of " << linear.transpose() << ": OCIO " << got.transpose()
                << ", expected " << want.transpose();
            const Vec back = apply(config, name, source, want);
            EXPECT_LT((back - linear).cwiseAbs().maxCoeff(), 2e-5)
                << name << " → " << source << " of " << want.transpose() << ": OCIO " << back.transpose();
        }
    }
}

TEST(ShippedOcioConfig, SrgbTextureDecodesHalfToTheIecValue) {
    // IEC 61966-2-1: ((0.5 + 0.055) / 1.055)^2.4 = 0.21404 (the config once encoded instead: 0.735).
    const double iec = std::pow((0.5 + 0.055) / 1.055, 2.4);
    EXPECT_NEAR(iec, 0.21404, 1e-5);
    const Vec got = apply(shipped(), "sRGB - Texture", "Linear Rec.709 (sRGB)", Vec(0.5, 0.5, 0.5));
    for (int c = 0; c < 3; ++c) EXPECT_NEAR(got[c], iec, 2e-5);
}

TEST(ShippedOcioConfig, EveryMaterialxColourSpaceNameResolvesToItsSpace) {
    // MaterialX 1.39's colour spaces (libraries/cmlib/cmlib_defs.mtlx, the *_to_lin_rec709 transforms; lin_srgb and
    // lin_ap1 are its aliases of lin_rec709 and acescg).
    const std::map<std::string, std::string> materialx{
        {"srgb_texture", "sRGB - Texture"},
        {"lin_rec709", "Linear Rec.709 (sRGB)"},
        {"lin_srgb", "Linear Rec.709 (sRGB)"},
        {"g22_rec709", "Gamma 2.2 Rec.709"},
        {"g18_rec709", "Gamma 1.8 Rec.709"},
        {"rec709_display", "Gamma 2.4 Rec.709"},
        {"acescg", "ACEScg"},
        {"lin_ap1", "ACEScg"},
        {"g22_ap1", "Gamma 2.2 AP1"},
        {"srgb_displayp3", "sRGB Encoded P3-D65"},
        {"lin_displayp3", "Linear P3-D65"},
        {"adobergb", "AdobeRGB"},
        {"lin_adobergb", "Linear AdobeRGB"},
    };
    for (const auto& [name, space] : materialx) {
        const auto resolved = shipped()->getColorSpace(name.c_str());
        ASSERT_TRUE(resolved) << name << " is not a space or alias of the shipped config";
        EXPECT_EQ(std::string(resolved->getName()), space) << name;
    }
}

TEST(ShippedOcioConfig, AliasesNameTheirOwnSpaceOnly) {
    const auto config = shipped();
    for (int i = 0; i < config->getNumColorSpaces(); ++i) {
        const auto space = config->getColorSpace(config->getColorSpaceNameByIndex(i));
        for (std::size_t a = 0; a < space->getNumAliases(); ++a)
            EXPECT_STREQ(config->getColorSpace(space->getAlias(a))->getName(), space->getName()) << space->getAlias(a);
    }
}

}  // namespace test_ocio_config
}  // namespace metalfit
