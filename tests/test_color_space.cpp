// OCIO colour spaces: the shipped config's transforms against matrices derived from primaries.
#include <gtest/gtest.h>
#include <unistd.h>

#include "test_support.hpp"

#include <Eigen/Dense>

#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <random>
#include <vector>

#include "libfit/base/errors.hpp"
#include "libfit/color/color_space.hpp"
#include "libfit/color/colorimetry.hpp"
#include "libfit/color/display_transform.hpp"

namespace metalfit {
namespace test_color_space {

using namespace metalfit::test;

const std::filesystem::path kConfig = kData / "ocio" / "config.ocio";
const OcioConfigChoice kShipped{kConfig, "test"};

// RGB → XYZ from primaries and white chromaticities (SMPTE RP 177), computed independently of OCIO.
Eigen::Matrix3d rgb_to_xyz(const double primaries[3][2], double wx, double wy) {
    auto xyz = [](double x, double y) { return Eigen::Vector3d(x / y, 1.0, (1.0 - x - y) / y); };
    Eigen::Matrix3d m;
    for (int c = 0; c < 3; ++c) m.col(c) = xyz(primaries[c][0], primaries[c][1]);
    const Eigen::Vector3d s = m.colPivHouseholderQr().solve(xyz(wx, wy));
    return m * s.asDiagonal();
}

// The XYZ → RGB matrix the converter applies, read off its images of the unit vectors.
Eigen::Matrix3d converter_matrix(const ColorSpaceConverter& convert) {
    Eigen::Matrix3d m;
    const XYZ basis[3] = {{1, 0, 0}, {0, 1, 0}, {0, 0, 1}};
    for (int c = 0; c < 3; ++c) {
        const RGB rgb = convert(basis[c]);
        m.col(c) = Eigen::Vector3d(rgb.r, rgb.g, rgb.b);
    }
    return m;
}

constexpr double kRec709[3][2] = {{0.64, 0.33}, {0.30, 0.60}, {0.15, 0.06}};
constexpr double kP3[3][2] = {{0.680, 0.320}, {0.265, 0.690}, {0.150, 0.060}};
constexpr double kRec2020[3][2] = {{0.708, 0.292}, {0.170, 0.797}, {0.131, 0.046}};

TEST(ColorSpace, XyzToLinearRec709IsTheMatrixOfThePrimaries) {
    const auto convert = ColorSpaceConverter::create(kShipped);  // role scene_linear
    EXPECT_EQ(convert.space(), "Linear Rec.709 (sRGB)");
    const Eigen::Matrix3d expected = rgb_to_xyz(kRec709, 0.3127, 0.3290).inverse();
    const Eigen::Matrix3d actual = converter_matrix(convert);
    EXPECT_LT((actual - expected).cwiseAbs().maxCoeff(), 1e-5) << "OCIO:\n" << actual << "\nprimaries:\n" << expected;
    // docs/colour.md, "The shipped config": first row 3.2409699, −1.5373832, −0.4986108 (IEC 61966-2-1 derived from its primaries and white).
    EXPECT_NEAR(actual(0, 0), 3.2409699, 1e-5);
    EXPECT_NEAR(actual(0, 1), -1.5373832, 1e-5);
    EXPECT_NEAR(actual(0, 2), -0.4986108, 1e-5);
}

TEST(ColorSpace, WideGamutSpacesAreTheMatricesOfTheirPrimaries) {
    for (const auto& [name, primaries] : {std::pair{"Linear P3-D65", kP3}, std::pair{"Linear Rec.2020", kRec2020}}) {
        const auto convert = ColorSpaceConverter::create(kShipped, name);
        const Eigen::Matrix3d expected = rgb_to_xyz(primaries, 0.3127, 0.3290).inverse();
        EXPECT_LT((converter_matrix(convert) - expected).cwiseAbs().maxCoeff(), 1e-5) << name;
    }
}

TEST(ColorSpace, PerfectReflectorUnderD65IsWhiteInEverySpace) {
    const XYZ white = Colorimetry::load(kData, Observer::cie1931_2deg, Illuminant::D65).white();
    for (const char* space : {"Linear Rec.709 (sRGB)", "ACEScg", "ACES2065-1", "Linear P3-D65", "Linear Rec.2020"}) {
        const RGB rgb = ColorSpaceConverter::create(kShipped, space)(white);
        for (int c = 0; c < 3; ++c) EXPECT_NEAR(rgb[c], 1.0, 1e-3) << space << " channel " << c;
    }
    // The D65 spectrum is not exactly at (0.3127, 0.3290): the offset docs/colour.md records ("White balance").
    const RGB rec709 = ColorSpaceConverter::create(kShipped)(white);
    EXPECT_NEAR(rec709.r, 1.00016, 2e-5);
    EXPECT_NEAR(rec709.b, 0.99976, 2e-5);
}

TEST(ColorSpace, AliasesAndRolesResolve) {
    EXPECT_EQ(ColorSpaceConverter::create(kShipped, "lin_rec2020").space(), "Linear Rec.2020");
    EXPECT_EQ(ColorSpaceConverter::create(kShipped, "compositing_linear").space(), "ACEScg");
}

TEST(ColorSpace, ManyColoursAtOnceAreTheValuesOfOneAtATime) {
    // to_xyz over a span applies OCIO once to a packed image (OCIO works through it in blocks of pixels); the result
    // must be what one applyRGB per colour gives, bit for bit, whatever the count (blocks and their remainders).
    std::mt19937_64 random(19);
    std::uniform_real_distribution<double> in_gamut(0.0, 1.0), wide(-0.5, 2.5);
    std::uniform_int_distribution<int> exponent(-30, 4);
    std::vector<RGB> colours;
    for (int i = 0; i < 5000; ++i) {
        if (i % 3 == 0)
            colours.emplace_back(wide(random), wide(random), wide(random));
        else if (i % 3 == 1)
            colours.emplace_back(in_gamut(random), in_gamut(random), in_gamut(random));
        else
            colours.emplace_back(std::ldexp(in_gamut(random), exponent(random)),
                                 std::ldexp(in_gamut(random), exponent(random)),
                                 std::ldexp(in_gamut(random), exponent(random)));
    }
    for (const char* space : {"Linear Rec.709 (sRGB)", "ACEScg", "ACES2065-1", "Linear P3-D65", "Linear Rec.2020"}) {
        const auto convert = ColorSpaceConverter::create(kShipped, space);
        for (const std::size_t count :
             {std::size_t{0}, std::size_t{1}, std::size_t{3}, std::size_t{127}, std::size_t{1153}, colours.size()}) {
            const std::vector<XYZ> many = convert.to_xyz(std::span<const RGB>(colours.data(), count));
            ASSERT_EQ(many.size(), count);
            for (std::size_t i = 0; i < count; ++i) {
                const XYZ one = convert.to_xyz(colours[i]);
                ASSERT_TRUE(many[i] == one)
                    << space << " count " << count << " colour " << i << ": " << many[i].X << " " << many[i].Y << " "
                    << many[i].Z << " against " << one.X << " " << one.Y << " " << one.Z;
            }
        }
    }
}

// This process's own folder: ctest runs each test as a process of its own, in parallel, and two of them remove the
// folder when they are done.
std::filesystem::path temp_config_dir() {
    return std::filesystem::temp_directory_path() / ("metalfit-test-ocio-" + std::to_string(::getpid()));
}

std::filesystem::path write_temp_config(const std::string& name, const std::string& text) {
    const auto dir = temp_config_dir();
    std::filesystem::create_directories(dir);
    const auto path = dir / name;
    std::ofstream(path) << text;
    return path;
}

void expect_config_error(const OcioConfigChoice& choice, const std::string& target, const std::string& must_contain) {
    try {
        ColorSpaceConverter::create(choice, target);
        ADD_FAILURE() << "no error for " << choice.path << " / " << target;
    } catch (const ColorConfigError& e) {
        const std::string what = e.what();
        EXPECT_NE(what.find(choice.path.string()), std::string::npos) << what;
        EXPECT_NE(what.find(must_contain), std::string::npos) << what;
        EXPECT_EQ(what.find('\n'), std::string::npos) << what;
    }
}

TEST(ColorSpace, ConfigurationProblemsNameTheConfig) {
    expect_config_error({"/nonexistent/config.ocio", "test"}, "", "cannot be loaded");
    expect_config_error(kShipped, "No Such Space", "No Such Space");
    expect_config_error(kShipped, "sRGB - Texture", "not linear");

    // The shipped config without the XYZ interchange role.
    std::ifstream in(kConfig);
    std::string text((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
    const std::string role = "  cie_xyz_d65_interchange: CIE-XYZ-D65\n";
    ASSERT_NE(text.find(role), std::string::npos);
    std::string no_role = text;
    no_role.erase(no_role.find(role), role.size());
    expect_config_error({write_temp_config("no-xyz-role.ocio", no_role), "test"}, "", "cie_xyz_d65_interchange");

    std::string no_scene_linear = text;
    const std::string scene = "  scene_linear: Linear Rec.709 (sRGB)\n";
    no_scene_linear.erase(no_scene_linear.find(scene), scene.size());
    expect_config_error({write_temp_config("no-scene-linear.ocio", no_scene_linear), "test"}, "", "scene_linear");
    std::filesystem::remove_all(temp_config_dir());
}

TEST(ColorSpace, EnvironmentVariableWinsOverCommandLineOverDefault) {
    const char* saved = std::getenv("OCIO");
    const std::string saved_value = saved ? saved : "";
    ::unsetenv("OCIO");
    EXPECT_EQ(choose_ocio_config(std::nullopt, "/data").path, std::filesystem::path("/data/ocio/config.ocio"));
    EXPECT_EQ(choose_ocio_config(std::nullopt, "/data").origin, "metalfit default");
    EXPECT_EQ(choose_ocio_config(std::filesystem::path("/cli.ocio"), "/data").path, "/cli.ocio");
    EXPECT_EQ(choose_ocio_config(std::filesystem::path("/cli.ocio"), "/data", "--ocio-config").origin, "--ocio-config");
    ::setenv("OCIO", "/env.ocio", 1);
    EXPECT_EQ(choose_ocio_config(std::filesystem::path("/cli.ocio"), "/data").path, "/env.ocio");
    EXPECT_EQ(choose_ocio_config(std::nullopt, "/data").origin, "$OCIO");
    if (saved)
        ::setenv("OCIO", saved_value.c_str(), 1);
    else
        ::unsetenv("OCIO");
}

// The display's encoding is measured (what glpreview's PNG chunks say): the shipped sRGB display is the sRGB curve on
// Rec.709 / D65; the same display made Rec.1886 (a pure 2.4 power law, Rec.709 primaries) is `gamma` 2.4; made
// Rec.1886 on Rec.2020 primaries it is `other` (no PNG chunk could say so); a config without the XYZ role is `other`.
TEST(DisplayTransform, TheDisplaysEncodingIsMeasuredThroughOcio) {
    const DisplayEncoding shipped = DisplayTransform::create(kShipped).encoding();
    EXPECT_EQ(shipped.kind, DisplayEncoding::Kind::srgb) << shipped.why;
    EXPECT_EQ(shipped.display_space, "sRGB - Display");

    std::ifstream in(kConfig);
    const std::string text((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
    const std::string srgb = "{style: DISPLAY - CIE-XYZ-D65_to_sRGB}";
    ASSERT_NE(text.find(srgb), std::string::npos);
    const auto with_display = [&](const std::string& name, const std::string& style) {
        std::string t = text;
        t.replace(t.find(srgb), srgb.size(), "{style: " + style + "}");
        return DisplayTransform::create({write_temp_config(name, t), "test"}).encoding();
    };
    const DisplayEncoding bt1886 = with_display("bt1886.ocio", "DISPLAY - CIE-XYZ-D65_to_REC.1886-REC.709");
    EXPECT_EQ(bt1886.kind, DisplayEncoding::Kind::gamma) << bt1886.why;
    EXPECT_NEAR(bt1886.gamma, 2.4, 1e-3);
    const DisplayEncoding rec2020 = with_display("rec2020.ocio", "DISPLAY - CIE-XYZ-D65_to_REC.1886-REC.2020");
    EXPECT_EQ(rec2020.kind, DisplayEncoding::Kind::other);
    EXPECT_NE(rec2020.why.find("primaries"), std::string::npos) << rec2020.why;

    std::string no_role = text;
    const std::string role = "  cie_xyz_d65_interchange: CIE-XYZ-D65\n";
    no_role.erase(no_role.find(role), role.size());
    const DisplayEncoding unmeasured =
        DisplayTransform::create({write_temp_config("no-role.ocio", no_role), "test"}).encoding();
    EXPECT_EQ(unmeasured.kind, DisplayEncoding::Kind::other);
    EXPECT_NE(unmeasured.why.find("cie_xyz_d65_interchange"), std::string::npos) << unmeasured.why;
    std::filesystem::remove_all(temp_config_dir());
}

}  // namespace test_color_space
}  // namespace metalfit
