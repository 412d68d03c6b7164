// Layered spheres in glpreview (issue 28 item 7): a film and a coat over a sphere's metal, and the named finishes, as
// scene keys; the sphere's reference curve and fits are the stack's. Checked against the limits the stack must meet
// (a film of 0 nm and a coat of index 1 are the bare metal; a finish is its metal with its layers) and the
// renderer's own CPU reference.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <string>

#include "glpreview/gl/gl_context.hpp"
#include "glpreview/render/preview.hpp"
#include "glpreview/render/sphere_fresnel.hpp"
#include "glpreview/scene/scene.hpp"
#include "libfit/base/errors.hpp"
#include "test_support.hpp"

namespace metalfit::glpreview {
namespace {

using test::kData;

Sphere titanium(const std::string& film = "", const std::string& coat = "") {
    Sphere s;
    s.material = "Ti";
    s.film = film;
    s.coat = coat;
    return s;
}

double largest_difference(const SphereFresnel& a, const SphereFresnel& b) {
    double most = 0;
    for (int i = 0; i <= 20; ++i) {
        const RGB x = a(i / 20.0), y = b(i / 20.0);
        most = std::max({most, std::abs(x.r - y.r), std::abs(x.g - y.g), std::abs(x.b - y.b)});
    }
    return most;
}

FresnelLibrary& library() {
    static FresnelLibrary lib(kData, choose_ocio_config(std::nullopt, kData), "", "layers.json");
    return lib;
}

TEST(PreviewLayers, TheStacksLimitsAreTheBareMetal) {
    const SphereFresnel& bare = library().get(titanium(), "spheres[0]");
    EXPECT_TRUE(bare.stack.empty());
    EXPECT_LT(largest_difference(library().get(titanium("TiO2:0nm"), "spheres[0]"), bare), 1e-12);
    EXPECT_LT(largest_difference(library().get(titanium("", "1"), "spheres[0]"), bare), 1e-12);
    const SphereFresnel& filmed = library().get(titanium("TiO2:60nm"), "spheres[0]");
    EXPECT_GT(largest_difference(filmed, bare), 0.05) << "a 60 nm oxide colours titanium";
    EXPECT_EQ(filmed.stack, "titanium under a TiO2 (Siefke) film of 60 nm");
    EXPECT_EQ(filmed.material, "titanium + TiO2 60 nm");  // what the sheet's labels and metrics.json call it
    EXPECT_EQ(bare.material, "titanium");
    EXPECT_EQ(library().get(titanium("2.2:120nm", "1.5"), "spheres[0]").material,
              "titanium + n = 2.2 120 nm + coat n = 1.5");
    // Blue at normal incidence: the first-order interference of ~60 nm TiO2 removes the red and green.
    EXPECT_GT(filmed(1.0).b, filmed(1.0).r);
    const SphereFresnel& coated = library().get(titanium("", "1.5"), "spheres[0]");
    EXPECT_LT(coated(1.0).g, bare(1.0).g) << "a coat of 1.5 lowers the metal's contrast at normal incidence";
}

TEST(PreviewLayers, AFinishIsItsMetalWithItsLayers) {
    Sphere finish;
    finish.material = "anodized-ti-80nm";
    const SphereFresnel& named = library().get(finish, "spheres[0]");
    EXPECT_LT(largest_difference(named, library().get(titanium("TiO2:80nm"), "spheres[0]")), 1e-12);
    EXPECT_TRUE(test::Contains(named.stack, "anodized titanium, 80 nm"));
    EXPECT_EQ(named.material, "anodized titanium, 80 nm");
    // A finish already has layers: more are refused, naming the key.
    finish.film = "TiO2:20nm";
    try {
        library().get(finish, "spheres[3]");
        ADD_FAILURE() << "no error";
    } catch (const InputError& e) {
        EXPECT_TRUE(test::Contains(e.what(), "layers.json: spheres[3].film: anodized-ti-80nm is a named finish"));
    }
}

TEST(PreviewLayers, BadLayersNameTheirKey) {
    auto load_error = [](const Sphere& s) -> std::string {
        try {
            library().get(s, "spheres[1]");
        } catch (const InputError& e) {
            return e.what();
        }
        return "no error";
    };
    EXPECT_TRUE(test::Contains(load_error(titanium("Unobtainium:80nm")), "spheres[1].film: --film Unobtainium:80nm"));
    EXPECT_TRUE(
        test::Contains(load_error(titanium("TiO2")), "spheres[1].film: --film TiO2: give the film's thickness"));
    EXPECT_TRUE(test::Contains(load_error(titanium("TiO2:-5nm")), "spheres[1].film: --film TiO2:-5nm: thickness"));
    EXPECT_TRUE(test::Contains(load_error(titanium("", "0.8")), "spheres[1].coat: --coat 0.8: index 0.8 is below 1"));
    auto parse_error = [](const std::string& sphere) -> std::string {
        try {
            parse_scene(R"({"spheres": [)" + sphere + "]}", "bad.json");
        } catch (const InputError& e) {
            return e.what();
        }
        return "no error";
    };
    EXPECT_TRUE(test::Contains(parse_error(R"({"center": [0, 1, 0], "film": "TiO2:80"})"),
                               "bad.json: spheres[0].film: --film TiO2:80: give the thickness's unit"));
    EXPECT_TRUE(test::Contains(parse_error(R"({"center": [0, 1, 0], "film": "oxide.csv:80nm"})"),
                               "bad.json: spheres[0].film: a file is not read from a scene"));
    EXPECT_TRUE(test::Contains(parse_error(R"({"center": [0, 1, 0], "coat": 1.5})"),
                               "bad.json: spheres[0].coat: expected a string"));
    const Scene good =
        parse_scene(R"({"spheres": [{"center": [0, 1, 0], "film": "2.2:120nm", "coat": "1.5"}]})", "s.json");
    EXPECT_EQ(good.spheres[0].film, "2.2:120nm");
    EXPECT_EQ(good.spheres[0].coat, "1.5");
}

// The GPU image of filmed and coated spheres agrees with the CPU reference as a bare sphere's does, and metrics.json
// names each stack.
TEST(PreviewLayers, LayeredSpheresRenderAgainstTheirReference) {
    static GlContext context = GlContext::create();
    const Scene scene = parse_scene(R"({"image": {"width": 160, "height": 60}, "environment": {"cube_size": 128},
        "camera": {"position": [0, 0.6, 3.2], "look_at": [0, 0.5, 0], "fov_y_deg": 30},
        "spheres": [{"center": [-1.0, 0.5, 0], "radius": 0.45, "material": "Ti"},
                    {"center": [0.0, 0.5, 0], "radius": 0.45, "material": "Ti", "film": "TiO2:60nm"},
                    {"center": [1.0, 0.5, 0], "radius": 0.45, "material": "Au", "coat": "1.5", "fresnel": "f82-tint"}],
        "outputs": {"exr": false, "png": false, "beauty": false, "reference": false, "difference": false}})",
                                    "layers.json");
    test::TempDir dir;
    const PreviewOptions options{kData, choose_ocio_config(std::nullopt, kData), dir.path(), 0};
    const PreviewResult result = run_preview(scene, options, &context);
    const auto& spheres = result.metrics.at("spheres");
    ASSERT_EQ(spheres.size(), 3u);
    EXPECT_TRUE(spheres[0].at("stack").is_null());
    EXPECT_EQ(spheres[1].at("stack"), "titanium under a TiO2 (Siefke) film of 60 nm");
    EXPECT_TRUE(test::Contains(spheres[2].at("stack").get<std::string>(), "coat n = 1.5"));
    const double bare = spheres[0].at("rmse").get<double>();
    EXPECT_LT(spheres[1].at("rmse").get<double>(), 3 * bare + 0.02);
    // The coated gold's f82-tint is fitted to the coated curve: its own error against that curve is small.
    EXPECT_LT(spheres[2].at("fit_rmse").get<double>(), 0.02);
}

}  // namespace
}  // namespace metalfit::glpreview
