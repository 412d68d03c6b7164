// Layered spheres in glpreview (issue 28 item 7): a film and a coat over a sphere's metal, and the named finishes, as
// scene keys; the sphere's reference curve and fits are the stack's. Checked against the limits the stack must meet
// (a film of 0 nm and a coat of index 1 are the bare metal; a finish is its metal with its layers) and the
// renderer's own CPU reference.
#include <gtest/gtest.h>

#include <sys/stat.h>

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <fstream>
#include <string>

#include "glpreview/gl/gl_context.hpp"
#include "glpreview/render/preview.hpp"
#include "glpreview/render/sphere_fresnel.hpp"
#include "glpreview/scene/scene.hpp"
#include "libfit/base/errors.hpp"
#include "test_support.hpp"

namespace metalfit::glpreview {
namespace test_preview_layers {

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
    EXPECT_TRUE(test::Contains(parse_error(R"({"center": [0, 1, 0], "coat": 1.5})"),
                               "bad.json: spheres[0].coat: expected a string"));
    const Scene good =
        parse_scene(R"({"spheres": [{"center": [0, 1, 0], "film": "2.2:120nm", "coat": "1.5"}]})", "s.json");
    EXPECT_EQ(good.spheres[0].film, "2.2:120nm");
    EXPECT_EQ(good.spheres[0].coat, "1.5");
}

// A film's or coat's file, beside the scene: read through metalfit's --film FILE importer, so a copy of a database film
// gives the named film's LUT bit for bit; its provenance names the file as the scene gave it, not the private link it
// is read through; a missing file, a link leading out of the scene's folder and a FIFO are refused naming the key.
TEST(PreviewLayers, FilmAndCoatFilesBesideTheSceneAreTheDatabasesLayers) {
    namespace fs = std::filesystem;
    test::TempDir top;
    const fs::path folder = top.path() / "scene", outside = top.path() / "outside";
    fs::create_directories(folder);
    fs::create_directories(outside);
    const fs::path scene_file = folder / "scene.json";
    fs::copy_file(kData / "films/TiO2/Siefke.yml", folder / "my-oxide.yml");
    fs::create_directories(folder / "coats");
    fs::copy_file(kData / "films/SiO2/Malitson.yml", folder / "coats/glass.yml");
    FresnelLibrary lib(kData, choose_ocio_config(std::nullopt, kData), "", scene_file, PathPolicy{kData, false});
    const auto same_lut = [](const SphereFresnel& a, const SphereFresnel& b) {
        EXPECT_EQ(a.lut.size(), b.lut.size());
        for (std::size_t i = 0; i < std::min(a.lut.size(), b.lut.size()); ++i)
            for (int c = 0; c < 3; ++c) EXPECT_EQ(a.lut[i][c], b.lut[i][c]) << "texel " << i << " channel " << c;
    };
    const SphereFresnel& from_file = lib.get(titanium("my-oxide.yml:60nm"), "spheres[1]");
    same_lut(from_file, lib.get(titanium("TiO2:60nm"), "spheres[1]"));
    EXPECT_GT(largest_difference(from_file, lib.get(titanium(), "spheres[1]")), 0.05) << "the film is there";
    same_lut(lib.get(titanium("my-oxide.yml:60nm", "coats/glass.yml"), "spheres[1]"),
             lib.get(titanium("TiO2:60nm", "SiO2"), "spheres[1]"));
    const Material layered = lib.material(titanium("my-oxide.yml:60nm", "coats/glass.yml"), "spheres[1]");
    ASSERT_TRUE(layered.layers && layered.layers->film && layered.layers->coat);
    EXPECT_EQ(layered.layers->film->material.provenance.file, folder / "my-oxide.yml");
    EXPECT_EQ(layered.layers->coat->material.provenance.file, folder / "coats/glass.yml");

    auto load_error = [&lib](const Sphere& s) -> std::string {
        try {
            lib.get(s, "spheres[1]");
        } catch (const InputError& e) {
            return e.what();
        }
        return "no error";
    };
    EXPECT_TRUE(test::Contains(load_error(titanium("missing.csv:60nm")), "scene.json: spheres[1].film: "))
        << load_error(titanium("missing.csv:60nm"));
    EXPECT_TRUE(test::Contains(load_error(titanium("missing.csv:60nm")), "missing.csv: cannot open it"));
    EXPECT_TRUE(test::Contains(load_error(titanium("", "missing.yml")), "scene.json: spheres[1].coat: "));
    // A link to a file in another folder, neither the scene's nor the database.
    fs::copy_file(kData / "films/TiO2/Siefke.yml", outside / "elsewhere.yml");
    fs::create_symlink(outside / "elsewhere.yml", folder / "link.yml");
    EXPECT_TRUE(test::Contains(load_error(titanium("link.yml:60nm")),
                               "scene.json: spheres[1].film: a path outside the scene's folder"))
        << load_error(titanium("link.yml:60nm"));
    ASSERT_EQ(::mkfifo((folder / "fifo.yml").c_str(), 0600), 0);
    EXPECT_TRUE(test::Contains(load_error(titanium("fifo.yml:60nm")), "spheres[1].film: "));
    EXPECT_TRUE(test::Contains(load_error(titanium("fifo.yml:60nm")), "not a regular file"));
    // A bad table in a file: the importer's message, naming the key and the file as the scene gave it.
    std::ofstream(folder / "broken.csv") << "wl,n,k\n0.5,2.0\n";
    const std::string broken = load_error(titanium("broken.csv:60nm"));
    EXPECT_TRUE(test::Contains(broken, "spheres[1].film: ")) << broken;
    EXPECT_TRUE(test::Contains(broken, (folder / "broken.csv").string())) << broken;
    EXPECT_FALSE(test::Contains(broken, "glpreview-file-")) << broken;

    // The scene's path check before any work names the key too.
    Scene scene = parse_scene(R"({"spheres": [{"center": [0, 1, 0], "material": "Ti", "film": "../oxide.yml:80nm"},
        {"center": [1, 1, 0], "material": "Ti", "coat": "/etc/coat.yml"}]})",
                              scene_file);
    try {
        confine_scene_paths(scene, PathPolicy{kData, false});
        ADD_FAILURE() << "no error";
    } catch (const InputError& e) {
        EXPECT_TRUE(test::Contains(e.what(), "spheres[0].film: a path outside the scene's folder")) << e.what();
    }
    scene.spheres[0].film = "my-oxide.yml:80nm";
    try {
        confine_scene_paths(scene, PathPolicy{kData, false});
        ADD_FAILURE() << "no error";
    } catch (const InputError& e) {
        EXPECT_TRUE(test::Contains(e.what(), "spheres[1].coat: a path outside the scene's folder")) << e.what();
    }
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

}  // namespace test_preview_layers
}  // namespace metalfit::glpreview
