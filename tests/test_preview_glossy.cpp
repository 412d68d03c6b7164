// Rough spheres (issue 17): the per-model DFG table against a direct integral, the CPU Monte-Carlo reference
// against the analytic mirror and its own error estimate, and on GL (llvmpipe in CI) the prefiltered method:
// furnace test, the limit roughness → 0, byte-identical mirrors.
#include <gtest/gtest.h>

#include <OpenEXR/ImfInputFile.h>
#include <OpenEXR/ImfStandardAttributes.h>
#include <stdlib.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <map>
#include <numbers>
#include <optional>

#include "glpreview/gl/gl_context.hpp"
#include "glpreview/io/image_io.hpp"
#include "glpreview/render/cpu_reference.hpp"
#include "glpreview/render/dfg_table.hpp"
#include "glpreview/render/environment.hpp"
#include "glpreview/render/features.hpp"
#include "glpreview/render/gpu_renderer.hpp"
#include "glpreview/render/monte_carlo_reference.hpp"
#include "glpreview/render/preview.hpp"
#include "glpreview/render/sphere_metrics.hpp"
#include "glpreview/scene/camera.hpp"
#include "libfit/color/color_space.hpp"
#include "test_support.hpp"

namespace metalfit::glpreview {
namespace test_preview_glossy {

using test::kData;

GlContext& gl() {
    static GlContext context = GlContext::create();
    return context;
}

const SphereFresnel& unit_fresnel() {
    static const SphereFresnel unit = [] {
        SphereFresnel f;
        f.lut.assign(2, RGB{1, 1, 1});
        return f;
    }();
    return unit;
}

FresnelLibrary& library() {
    static FresnelLibrary lib(kData, choose_ocio_config(std::nullopt, kData), "", "test.json");
    return lib;
}

const SphereFresnel& fresnel_of(const std::string& material, const std::string& model) {
    Sphere s;
    s.material = material;
    if (model != "reference") s.fresnel = ModelFresnel{model, ParameterSource::fit};
    return library().get(s, "spheres[0]");
}

// The lobe integral written out independently of ggx.cpp and dfg_table.cpp: a midpoint rule over the light
// direction in spherical coordinates, ∫ F(v·h) D(h) G2(v, l) / (4 n·v) dl, with the height-correlated Smith G2.
RGB direct_integral(const SphereFresnel& f, double mu, double roughness) {
    const double a = roughness * roughness, a2 = a * a;
    const double pi = std::numbers::pi;
    auto lambda = [&](double cos_t) {
        const double tan2 = (1 - cos_t * cos_t) / (cos_t * cos_t);
        return 0.5 * (-1 + std::sqrt(1 + a2 * tan2));
    };
    const Vec3 v{std::sqrt(1 - mu * mu), 0, mu};
    const int nt = 320, np = 320;
    RGB sum{0, 0, 0};
    for (int i = 0; i < nt; ++i) {
        const double theta = (i + 0.5) * (pi / 2) / nt;
        for (int j = 0; j < np; ++j) {
            const double phi = (j + 0.5) * pi / np;  // the integrand is symmetric in φ ↦ −φ
            const Vec3 l{std::sin(theta) * std::cos(phi), std::sin(theta) * std::sin(phi), std::cos(theta)};
            const Vec3 h = normalize(v + l);
            const double d = h.z * h.z * (a2 - 1) + 1;
            const double D = a2 / (pi * d * d);
            const double G2 = 1 / (1 + lambda(mu) + lambda(l.z));
            const double w = D * G2 / (4 * mu) * std::sin(theta) * (pi / 2 / nt) * (pi / np) * 2;
            sum += w * f(dot(v, h));
        }
    }
    return sum;
}

TEST(DfgTable, EqualsADirectIntegralOfTheSpheresOwnFresnel) {
    for (const auto& [material, model] :
         {std::pair{"Au", "reference"}, std::pair{"Cu", "f82-tint"}, std::pair{"Al", "schlick"}}) {
        const SphereFresnel& f = fresnel_of(material, model);
        const DfgTable table = make_dfg_table(f);
        // Roughness 0: F(μ) itself.
        for (int i : {0, 9, 31}) {
            const RGB mirror = table.at(i, 0), exact = f(i / 31.0);
            for (int c = 0; c < 3; ++c) EXPECT_NEAR(mirror[c], exact[c], 1e-12) << material;
        }
        for (int i : {6, 16, 28})
            for (int j : {5, 16}) {
                const double mu = i / double(DfgTable::kMuSize - 1), r = j / double(DfgTable::kRoughnessSize - 1);
                const RGB expected = direct_integral(f, mu, r), got = table.at(i, j);
                for (int c = 0; c < 3; ++c)
                    EXPECT_NEAR(got[c], expected[c], 2e-3)
                        << material << " " << model << " mu " << mu << " roughness " << r << " channel " << c;
            }
    }
}

TEST(DfgTable, DiffersBetweenModelsOfTheSameMaterial) {
    // The table integrates the sphere's own curve: two models of one metal give two tables (at least where their
    // curves differ, near grazing).
    const SphereFresnel &a = fresnel_of("Al", "schlick"), &b = fresnel_of("Al", "reference");
    double largest = 0;
    for (double mu : {0.05, 0.2, 0.5})
        for (double r : {0.25, 0.5, 1.0})
            for (int c = 0; c < 3; ++c)
                largest = std::max(largest, std::abs(dfg_integral(a, mu, r)[c] - dfg_integral(b, mu, r)[c]));
    EXPECT_GT(largest, 1e-3);
}

Scene room_scene(double roughness, int w = 48, int h = 36) {
    Scene scene;
    scene.file = "test-scene.json";
    scene.width = w;
    scene.height = h;
    scene.camera.position = {0, 1.1, 2.2};
    scene.environment.reference_point = Vec3{0, 1.2, 0};
    scene.environment.cube_size = 64;
    scene.environment.room.panels = {{-1, -1, 1, 1, {6, 6, 6}}};
    Sphere sphere;
    sphere.center = {0.0, 1.0, 0.0};
    sphere.roughness = roughness;
    sphere.reflection = ReflectionMode::box_parallax;
    scene.spheres = {sphere};
    return scene;
}

Scene furnace_scene(double roughness) {
    Scene scene = room_scene(roughness, 64, 48);
    scene.environment.type = EnvironmentType::sphere_room;
    scene.environment.sphere_room.light = scene.environment.sphere_room.dark = RGB{1, 1, 1};
    scene.environment.reference_point = Vec3{0, 1, 0};
    scene.spheres[0].reflection = ReflectionMode::classic;
    return scene;
}

TEST(MonteCarloReference, AtVanishingRoughnessItIsTheAnalyticMirror) {
    Scene scene = room_scene(1e-3);
    const std::vector<const SphereFresnel*> fresnel{&fresnel_of("Au", "reference")};
    const EnvironmentTracer tracer(scene.environment);
    const ReferenceRender analytic = render_reference(scene, fresnel, tracer, 2);
    const MonteCarloReference mc = render_monte_carlo_reference(scene, fresnel, tracer, analytic, 8, 2);
    const auto e = sphere_errors(mc.render.image, analytic, 1);
    ASSERT_GT(e[0].pixels, 200u);
    EXPECT_LT(e[0].rmse, 1e-4);
    EXPECT_LT(sphere_reference_noise(mc.standard_error, analytic, 1)[0], 1e-3);
    // Roughness 0 is the mirror path itself: the pixels are the analytic ones.
    scene.spheres[0].roughness = 0;
    const MonteCarloReference exact = render_monte_carlo_reference(scene, fresnel, tracer, analytic, 8, 2);
    EXPECT_EQ(exact.render.image.rgb, analytic.image.rgb);
    // A real lobe does change the image.
    scene.spheres[0].roughness = 0.4;
    const MonteCarloReference rough = render_monte_carlo_reference(scene, fresnel, tracer, analytic, 8, 2);
    EXPECT_GT(sphere_errors(rough.render.image, analytic, 1)[0].rmse, 1e-2);
}

TEST(MonteCarloReference, DoesNotDependOnTheThreadCount) {
    const Scene scene = room_scene(0.3, 24, 18);
    const std::vector<const SphereFresnel*> fresnel{&fresnel_of("Au", "reference")};
    const EnvironmentTracer tracer(scene.environment);
    const ReferenceRender analytic = render_reference(scene, fresnel, tracer, 1);
    const auto one = render_monte_carlo_reference(scene, fresnel, tracer, analytic, 8, 1);
    const auto three = render_monte_carlo_reference(scene, fresnel, tracer, analytic, 8, 3);
    EXPECT_EQ(one.render.image.rgb, three.render.image.rgb);
    EXPECT_EQ(one.standard_error.rgb, three.standard_error.rgb);
}

TEST(MonteCarloReference, ItsStandardErrorDescribesItsDeviation) {
    // 16 samples against 1024 taken as the truth: the mean squared deviation over the sphere's pixels and channels
    // equals the mean squared standard error (σ²/N both; the sample variance is unbiased whatever the distribution's
    // shape). A standard error off by √N or by 2 puts the ratio near 16, 1/16, 4 or 1/4.
    const Scene scene = room_scene(0.35, 32, 24);
    const std::vector<const SphereFresnel*> fresnel{&fresnel_of("Cu", "reference")};
    const EnvironmentTracer tracer(scene.environment);
    const ReferenceRender analytic = render_reference(scene, fresnel, tracer, 2);
    const auto few = render_monte_carlo_reference(scene, fresnel, tracer, analytic, 16, 2);
    const auto many = render_monte_carlo_reference(scene, fresnel, tracer, analytic, 1024, 2);
    double deviation = 0, error = 0;
    std::size_t count = 0;
    for (std::size_t p = 0; p < analytic.sphere_id.size(); ++p) {
        if (analytic.sphere_id[p] < 0) continue;
        for (int c = 0; c < 3; ++c) {
            deviation +=
                std::pow(double(few.render.image.rgb[3 * p + c]) - double(many.render.image.rgb[3 * p + c]), 2);
            error += std::pow(double(few.standard_error.rgb[3 * p + c]), 2);
            ++count;
        }
    }
    ASSERT_GT(count, 300u);
    const double ratio = deviation / error;
    EXPECT_GT(ratio, 0.75) << ratio;
    EXPECT_LT(ratio, 1.33) << ratio;
}

TEST(MonteCarloReference, FurnaceEqualsTheLobeIntegral) {
    // A uniform white environment and F ≡ 1: every pixel is the directional albedo of its μ, the table's integral.
    const Scene scene = furnace_scene(0.6);
    const std::vector<const SphereFresnel*> fresnel{&unit_fresnel()};
    const EnvironmentTracer tracer(scene.environment);
    const ReferenceRender analytic = render_reference(scene, fresnel, tracer, 2);
    const auto mc = render_monte_carlo_reference(scene, fresnel, tracer, analytic, 256, 2);
    const CameraBasis basis = camera_basis(scene.camera, scene.width, scene.height);
    int checked = 0;
    for (int py = 0; py < scene.height; ++py)
        for (int px = 0; px < scene.width; ++px) {
            const int row = scene.height - 1 - py;
            if (analytic.sphere_id[static_cast<std::size_t>(row) * scene.width + px] != 0) continue;
            const Vec3 d = camera_ray(basis, px, py, scene.width, scene.height);
            const Vec3 oc = basis.position - scene.spheres[0].center;
            const double b = dot(oc, d), t = -b - std::sqrt(b * b - (dot(oc, oc) - 0.25));
            const double mu = -dot(d, normalize(basis.position + t * d - scene.spheres[0].center));
            const double expected = dfg_integral(unit_fresnel(), mu, 0.6).r;
            EXPECT_NEAR(mc.render.image.at(px, row).r, expected, 4 * mc.standard_error.at(px, row).r + 1e-3) << mu;
            ++checked;
        }
    EXPECT_GT(checked, 200);
}

// --- the prefiltered method on GL ---

// Per sphere pixel (top row first) the μ of its camera ray, as the CPU reference computes it; −1 elsewhere.
std::vector<double> sphere_mu(const Scene& scene) {
    std::vector<double> out(static_cast<std::size_t>(scene.width) * scene.height, -1);
    const CameraBasis basis = camera_basis(scene.camera, scene.width, scene.height);
    const Sphere& s = scene.spheres[0];
    for (int py = 0; py < scene.height; ++py)
        for (int px = 0; px < scene.width; ++px) {
            const Vec3 d = camera_ray(basis, px, py, scene.width, scene.height);
            const Vec3 oc = basis.position - s.center;
            const double b = dot(oc, d), disc = b * b - (dot(oc, oc) - s.radius * s.radius);
            if (disc < 0) continue;
            const double t = -b - std::sqrt(disc);
            out[static_cast<std::size_t>(scene.height - 1 - py) * scene.width + px] =
                -dot(d, normalize(basis.position + t * d - s.center));
        }
    return out;
}

TEST(PreviewGlossy, FurnaceEqualsTheDfgTablesOwnIntegral) {
    gl();
    for (double roughness : {0.3, 0.75}) {
        const Scene scene = furnace_scene(roughness);
        GpuRenderer gpu(scene, plan_features(scene), {&unit_fresnel()}, nullptr);
        gpu.capture_environment();
        const Image beauty = gpu.render();
        const DfgTable table = make_dfg_table(unit_fresnel());
        const std::vector<double> mu = sphere_mu(scene);
        double worst = 0;
        int checked = 0;
        for (int y = 0; y < scene.height; ++y)
            for (int x = 0; x < scene.width; ++x) {
                const double m = mu[static_cast<std::size_t>(y) * scene.width + x];
                if (m < 0.05) continue;  // the silhouette: a pixel's centre may miss the sphere on one side only
                const double expected = table(m, roughness).r;
                worst = std::max(worst, std::abs(beauty.at(x, y).r - expected));
                ++checked;
            }
        EXPECT_GT(checked, 500);
        EXPECT_LT(worst, 1e-3) << "roughness " << roughness;
        EXPECT_LT(table(0.9, roughness).r, 1.0);  // a rough lobe loses energy (single scattering): not the trivial 1
    }
}

// Issue 32 (glpreview --sheet-rows: each row's Fresnel made and let go): what effects keep for a Fresnel (the mirror's
// reference LUT, a rough sphere's DFG table) is keyed by its address. After GpuRenderer::forget_fresnel a new Fresnel
// made at that address is drawn with its own curve, as a fresh renderer draws it, not with the old one's textures.
TEST(PreviewGlossy, AFresnelMadeWhereAForgottenOneWasIsDrawnWithItsOwnCurve) {
    gl();
    const auto constant = [](double value) {
        SphereFresnel f;
        f.lut.assign(2, RGB{value, value, value});
        return f;
    };
    for (double roughness : {0.0, 0.5}) {
        SCOPED_TRACE(roughness);
        const Scene scene = furnace_scene(roughness);
        std::optional<SphereFresnel> slot;
        slot.emplace(constant(1.0));
        const SphereFresnel* address = &*slot;
        GpuRenderer gpu(scene, plan_features(scene), {address}, nullptr);
        gpu.capture_environment();
        const Image white = gpu.render();
        gpu.forget_fresnel(*slot);
        slot.emplace(constant(0.5));
        ASSERT_EQ(&*slot, address);
        const Image half = gpu.render();
        GpuRenderer fresh(scene, plan_features(scene), {&*slot}, nullptr);
        fresh.capture_environment();
        EXPECT_EQ(half.rgb, fresh.render().rgb);
        EXPECT_NE(half.rgb, white.rgb);
    }
}

double sphere_rmse(const Image& a, const Image& b, const std::vector<double>& mu) {
    double sum = 0;
    std::size_t n = 0;
    for (std::size_t p = 0; p < mu.size(); ++p) {
        if (mu[p] < 0) continue;
        for (int c = 0; c < 3; ++c) sum += std::pow(double(a.rgb[3 * p + c]) - double(b.rgb[3 * p + c]), 2);
        n += 3;
    }
    return std::sqrt(sum / double(n));
}

TEST(PreviewGlossy, PrefilteredAtVanishingRoughnessIsTheMirrorRender) {
    gl();
    const std::vector<const SphereFresnel*> fresnel{&fresnel_of("Au", "reference")};
    auto render = [&](const Scene& scene) {
        GpuRenderer gpu(scene, plan_features(scene), fresnel, nullptr);
        gpu.capture_environment();
        return gpu.render();
    };
    const Scene mirror = room_scene(0, 64, 48);
    const Image reference = render(mirror);
    const std::vector<double> mu = sphere_mu(mirror);
    const double near_zero = sphere_rmse(render(room_scene(1e-3, 64, 48)), reference, mu);
    const double rough = sphere_rmse(render(room_scene(0.3, 64, 48)), reference, mu);
    EXPECT_LT(near_zero, 3e-3);
    EXPECT_GT(rough, 10 * near_zero);
}

TEST(PreviewGlossy, RoughnessZeroGivesTodaysImagesByteForByte) {
    gl();
    const std::string spheres = R"([{"center": [-0.6, 0.9, 0], "radius": 0.45, "reflection": "classic"},
        {"center": [0.0, 0.9, 0], "radius": 0.45, "material": "Cu", "fresnel": "schlick", "reflection": "box-parallax"},
        {"center": [0.6, 0.9, 0], "radius": 0.45, "material": "Al"}])";
    const std::string with_key =
        R"([{"center": [-0.6, 0.9, 0], "radius": 0.45, "reflection": "classic", "roughness": 0},
        {"center": [0.0, 0.9, 0], "radius": 0.45, "material": "Cu", "fresnel": "schlick", "reflection": "box-parallax", "roughness": 0, "glossy": "prefiltered"},
        {"center": [0.6, 0.9, 0], "radius": 0.45, "material": "Al", "roughness": 0.0}])";
    auto run = [&](const std::string& s, const std::string& dir) {
        const Scene scene = parse_scene(
            R"({"image": {"width": 64, "height": 48}, "environment": {"cube_size": 64}, "spheres": )" + s + "}",
            "scene.json");
        PreviewOptions options{kData, choose_ocio_config(std::nullopt, kData), dir, 0};
        return run_preview(scene, options, &gl());
    };
    test::TempDir dir;
    ::setenv("SOURCE_DATE_EPOCH", "1764547200", 1);  // the EXRs' capture date (2025-12-01), so that bytes can be equal
    const PreviewResult today = run(spheres, (dir.path() / "a").string());
    const PreviewResult zero = run(with_key, (dir.path() / "b").string());
    ::unsetenv("SOURCE_DATE_EPOCH");
    ASSERT_TRUE(today.beauty && zero.beauty && today.reference && zero.reference);
    EXPECT_EQ(today.beauty->rgb, zero.beauty->rgb);
    EXPECT_EQ(today.reference->image.rgb, zero.reference->image.rgb);
    // The files are the same bytes: the pixels, and the headers (the capture date is $SOURCE_DATE_EPOCH's).
    for (const char* file :
         {"beauty.exr", "beauty.png", "reference.exr", "reference.png", "difference.exr", "difference.png"})
        EXPECT_EQ(test::read_file(dir.path() / "a" / file), test::read_file(dir.path() / "b" / file)) << file;
    const Imf::InputFile exr((dir.path() / "b" / "beauty.exr").c_str());
    ASSERT_TRUE(Imf::hasCapDate(exr.header()));
    EXPECT_EQ(Imf::capDate(exr.header()), "2025:12:01 00:00:00");
    EXPECT_FALSE(std::filesystem::exists(dir.path() / "b" / "reference-stderr.exr"));
    EXPECT_FALSE(zero.reference_standard_error);
    EXPECT_EQ(zero.metrics["spheres"][1]["roughness"], 0.0);
    EXPECT_TRUE(zero.metrics["spheres"][1]["glossy"].is_null());
}

TEST(PreviewGlossy, ARoughSceneRunsThroughTheGraphWithItsNoiseInTheMetrics) {
    gl();
    const Scene scene = parse_scene(R"({"image": {"width": 48, "height": 36}, "environment": {"cube_size": 64},
        "spheres": [{"center": [-0.5, 0.9, 0], "radius": 0.45, "roughness": 0.3},
                    {"center": [0.5, 0.9, 0], "radius": 0.45, "material": "Cu", "fresnel": "f82-tint", "roughness": 0.6, "reflection": "box-parallax"}],
        "outputs": {"reference_samples": 32, "png": false}})",
                                    "scene.json");
    test::TempDir dir;
    PreviewOptions options{kData, choose_ocio_config(std::nullopt, kData), dir.path(), 0};
    const PreviewResult result = run_preview(scene, options, &gl());
    ASSERT_TRUE(result.reference_standard_error);
    EXPECT_TRUE(std::filesystem::exists(dir.path() / "reference-stderr.exr"));
    for (int i = 0; i < 2; ++i) {
        const auto& s = result.metrics["spheres"][i];
        EXPECT_EQ(s["glossy"], "prefiltered");
        EXPECT_DOUBLE_EQ(s["roughness"].get<double>(), i == 0 ? 0.3 : 0.6);
        EXPECT_GT(s["reference_noise"].get<double>(), 0.0);
        EXPECT_LT(s["reference_noise"].get<double>(), s["rmse"].get<double>() + 0.1);
        EXPECT_LT(s["rmse"].get<double>(), 0.3);  // the split sum near the Monte-Carlo truth, not a mirror
    }
}

}  // namespace test_preview_glossy
}  // namespace metalfit::glpreview

namespace metalfit::glpreview {
namespace test_preview_glossy {

// --- the localized method (thesis ch. 5) on GL ---

Scene localized(Scene scene, int m) {
    scene.spheres[0].glossy = GlossyMethod::localized;
    scene.spheres[0].localized_size = m;
    return scene;
}

// A white furnace, F ≡ 1: the localized sum equals the DFG table's integral within 1e-3 on average over the sphere
// (and 1e-2 at its worst pixel, near the silhouette), at the roughness values and M it was tuned on (0.75–1, M = 8
// and 16; 0.5 at M = 4, where the lobe is narrower than a light and the lights are subdivided) and at ones it was
// not (0.55, 0.9; M = 4, 6, 12, where 64 source texels per edge do not divide into M blocks). The plain thesis sum
// missed this by 1.1e-3–2.3e-3 at roughness 0.75–1 and by 0.049 at roughness 0.5, M = 4 (docs/preview.md).
TEST(PreviewLocalizedGlossy, FurnaceEqualsTheDfgTablesIntegral) {
    gl();
    const DfgTable table = make_dfg_table(unit_fresnel());
    for (const auto& [roughness, m] : {std::pair{0.5, 4}, std::pair{0.75, 16}, std::pair{1.0, 8}, std::pair{1.0, 16},
                                       std::pair{0.55, 4}, std::pair{0.55, 6}, std::pair{0.55, 12}, std::pair{0.9, 4},
                                       std::pair{0.9, 6}, std::pair{0.9, 12}, std::pair{0.75, 6}, std::pair{1.0, 12}}) {
        const Scene scene = localized(furnace_scene(roughness), m);
        GpuRenderer gpu(scene, plan_features(scene), {&unit_fresnel()}, nullptr);
        gpu.capture_environment();
        const Image beauty = gpu.render();
        const std::vector<double> mu = sphere_mu(scene);
        double worst = 0, sum = 0;
        int n = 0;
        for (int y = 0; y < scene.height; ++y)
            for (int x = 0; x < scene.width; ++x) {
                const double c = mu[static_cast<std::size_t>(y) * scene.width + x];
                if (c < 0.05) continue;
                const double e = std::abs(beauty.at(x, y).r - table(c, roughness).r);
                worst = std::max(worst, e);
                sum += e;
                ++n;
            }
        ASSERT_GT(n, 500);
        std::printf("furnace, localized, roughness %.2f, M = %2d (k = %d): mean |error| %.5f, worst %.5f\n", roughness,
                    m, localized_subdivisions(roughness, m), sum / n, worst);
        EXPECT_LT(sum / n, 1e-3) << roughness << " " << m;
        EXPECT_LT(worst, 1e-2) << roughness << " " << m;
    }
}

// Why the thesis's plain sum missed the furnace (docs/preview.md, "Why"): a CPU replica in double of that sum —
// lights at the texel averages of the sphere room's 64² cube, solid angle Δω* (point-to-disc), the BRDF at each
// light's centre, a light counted when its centre is above the horizon — against a fine quadrature of each light's
// own region (4 samples per source texel, seen from x). Error = A (Δω* against the region's solid angle from x) +
// B (the horizon: straddling lights whole or not at all) + C (the BRDF over the light) + the table's own error.
// The lights as patches facing o, Δω · r²/r*² · cos γ (the shader's form), tile the sphere; the discs do not.
TEST(PreviewLocalizedGlossy, TheThesisSumsFurnaceErrorDecomposes) {
    const double pi = std::numbers::pi;
    const DfgTable table = make_dfg_table(unit_fresnel());
    auto cube = [](int f, double s, double t) -> Vec3 {
        switch (f) {
            case 0: return {1, -t, -s};
            case 1: return {-1, -t, s};
            case 2: return {s, 1, t};
            case 3: return {s, -1, -t};
            case 4: return {s, -t, 1};
            default: return {-s, -t, -1};
        }
    };
    auto corner = [](double s, double t) { return std::atan2(s * t, std::sqrt(s * s + t * t + 1)); };
    auto rect = [&](double s0, double s1, double t0, double t1) {
        return corner(s1, t1) - corner(s0, t1) - corner(s1, t0) + corner(s0, t0);
    };
    const int S = 64;
    const double room = 4;
    for (const auto& [roughness, m] : {std::pair{0.75, 16}, std::pair{1.0, 8}}) {
        const double a = roughness * roughness, a2 = a * a;
        auto lambda = [&](double c) { return 0.5 * (-1 + std::sqrt(1 + a2 * (1 - c * c) / std::max(c * c, 1e-12))); };
        auto lobe = [&](Vec3 n, Vec3 v, Vec3 l, double mu) {  // f_r cos θ for F ≡ 1
            if (dot(n, l) <= 0) return 0.0;
            const double nh = dot(n, normalize(v + l)), d = nh * nh * (a2 - 1) + 1;
            return a2 / (pi * d * d) / (1 + lambda(mu) + lambda(dot(n, l))) / (4 * mu);
        };
        struct Light {
            Vec3 y;
            double dw;
            int face, i, j;
        };
        std::vector<Light> lights;
        const int b = S / m;
        for (int f = 0; f < 6; ++f)
            for (int j = 0; j < m; ++j)
                for (int i = 0; i < m; ++i) {
                    Vec3 y{0, 0, 0};
                    for (int q = j * b; q < (j + 1) * b; ++q)
                        for (int p = i * b; p < (i + 1) * b; ++p)
                            y = y + room * normalize(cube(f, 2.0 * (p + 0.5) / S - 1, 2.0 * (q + 0.5) / S - 1));
                    const double s0 = -1 + 2.0 * i / m, t0 = -1 + 2.0 * j / m;
                    lights.push_back({(1.0 / (b * b)) * y, rect(s0, s0 + 2.0 / m, t0, t0 + 2.0 / m), f, i, j});
                }
        Scene scene = furnace_scene(roughness);
        scene.width = 32, scene.height = 24;  // the GL test's view at half its resolution
        const CameraBasis basis = camera_basis(scene.camera, scene.width, scene.height);
        const Vec3 o = scene.environment.reference();
        double error = 0, A = 0, B = 0, C = 0, T = 0, discs = 0, tiles = 0, tile_error = 0;
        int n = 0;
        for (int py = 0; py < scene.height; ++py)
            for (int px = 0; px < scene.width; ++px) {
                const Vec3 d = camera_ray(basis, px, py, scene.width, scene.height);
                const Vec3 oc = basis.position - scene.spheres[0].center;
                const double bb = dot(oc, d), disc = bb * bb - (dot(oc, oc) - 0.25);
                if (disc < 0) continue;
                const Vec3 p = basis.position + (-bb - std::sqrt(disc)) * d,
                           nrm = normalize(p - scene.spheres[0].center), v = -d;
                const double mu = dot(v, nrm);
                if (mu < 0.05) continue;
                const Vec3 x = p - o;
                double thesis = 0, exact_angle = 0, horizon = 0, exact = 0, tiled = 0;
                for (const Light& li : lights) {
                    const Vec3 to = li.y - x;
                    const double rs = std::sqrt(dot(to, to)), r = std::sqrt(dot(li.y, li.y));
                    const Vec3 l = (1 / rs) * to;
                    const double k = 2 * pi / (2 * pi - li.dw);
                    const double dw_star = 2 * pi * (1 - 1 / std::sqrt(1 + (k * k - 1) * r * r / (rs * rs)));
                    const double tile = li.dw * r * r / (rs * rs) * dot((1 / r) * li.y, l);
                    discs += dw_star, tiles += tile;
                    const double centre = lobe(nrm, v, l, mu);
                    if (dot(nrm, l) > 0) tiled += centre * tile;
                    double region = 0, region_integral = 0;
                    int above = 0, below = 0;
                    for (int q = 2 * li.j * b; q < 2 * (li.j + 1) * b; ++q)
                        for (int pp = 2 * li.i * b; pp < 2 * (li.i + 1) * b; ++pp) {
                            const double s0 = -1 + pp / double(S), t0 = -1 + q / double(S);
                            const Vec3 dir = normalize(cube(li.face, s0 + 0.5 / S, t0 + 0.5 / S));
                            const Vec3 w = room * dir - x;
                            const double rw = std::sqrt(dot(w, w));
                            const Vec3 lw = (1 / rw) * w;
                            const double omega =
                                rect(s0, s0 + 1.0 / S, t0, t0 + 1.0 / S) * room * room / (rw * rw) * dot(dir, lw);
                            region += omega;
                            region_integral += lobe(nrm, v, lw, mu) * omega;
                            (dot(nrm, lw) > 0 ? above : below) += 1;
                        }
                    exact += region_integral;
                    if (dot(nrm, l) > 0) thesis += centre * dw_star, exact_angle += centre * region;
                    horizon += above && below ? region_integral : above ? centre * region : 0;
                }
                const double expected = table(mu, roughness).r;
                error += thesis - expected, tile_error += std::abs(tiled - expected);
                A += thesis - exact_angle, B += exact_angle - horizon, C += horizon - exact, T += exact - expected;
                ++n;
            }
        ASSERT_GT(n, 100);
        std::printf(
            "thesis's sum, roughness %.2f, M = %2d: error %+.5f = A (dw*) %+.5f + B (horizon) %+.5f + C (BRDF over the light) %+.5f"
            " + table %+.5f; sum of dw* %.4f, of the tiles %.4f (4 pi %.4f); the tiles' sum: mean |error| %.5f\n",
            roughness, m, error / n, A / n, B / n, C / n, T / n, discs / n, tiles / n, 4 * pi, tile_error / n);
        EXPECT_GT(error / n, 1e-3);                     // the thesis's sum misses the issue's 1e-3
        EXPECT_GT(A / n, 1e-3);                         // and Δω* is its largest term
        EXPECT_GT(discs / n - 4 * pi, 3e-3 * 4 * pi);   // the discs cover more than the sphere
        EXPECT_NEAR(tiles / n, 4 * pi, 1e-4 * 4 * pi);  // the patches tile it
        EXPECT_NEAR(T / n, 0, 1e-4);                    // the table is not the cause
        EXPECT_LT(tile_error / n, 5e-4);
    }
}

TEST(PreviewLocalizedGlossy, LightsAreSubdividedWhereTheLobeIsNarrowerThanALight) {
    // k = 6 / (α M) rounded, within [1, ⌈16 / M⌉]: one sample per light for a broad lobe, finer for a narrow one, never
    // (much) finer than M = 16.
    EXPECT_EQ(localized_subdivisions(1.0, 8), 1);
    EXPECT_EQ(localized_subdivisions(1.0, 4), 2);
    EXPECT_EQ(localized_subdivisions(0.5, 4), 4);
    EXPECT_EQ(localized_subdivisions(0.5, 16), 1);
    EXPECT_EQ(localized_subdivisions(0.05, 2), 8);
    EXPECT_EQ(localized_subdivisions(0.05, 6), 3);
    // The shader gets k as a compile-time constant.
    const Scene scene = localized(furnace_scene(0.5), 4);
    const std::vector<std::string> defines = sphere_defines(scene, scene.spheres[0]);
    EXPECT_NE(std::find(defines.begin(), defines.end(), "LOCALIZED_SUBDIVISIONS 4"), defines.end());
    for (int m = 2; m <= 16; ++m)
        for (double r : {0.01, 0.1, 0.3, 0.6, 1.0}) {
            EXPECT_GE(localized_subdivisions(r, m), 1);
            EXPECT_LT((localized_subdivisions(r, m) - 1) * m, 16);
            EXPECT_GE(localized_subdivisions(r, m), localized_subdivisions(std::min(1.0, r + 0.1), m));
        }
}

TEST(PreviewLocalizedGlossy, GrowingMApproachesTheMonteCarloReference) {
    gl();
    Scene scene = room_scene(0.6, 64, 48);
    scene.spheres[0].reflection = ReflectionMode::classic;  // the prefiltered lookup unlocalized: its parallax shows
    const std::vector<const SphereFresnel*> fresnel{&fresnel_of("Au", "reference")};
    const EnvironmentTracer tracer(scene.environment);
    const ReferenceRender analytic = render_reference(scene, fresnel, tracer, 2);
    const MonteCarloReference mc = render_monte_carlo_reference(scene, fresnel, tracer, analytic, 512, 2);
    const double noise = sphere_reference_noise(mc.standard_error, analytic, 1)[0];
    std::map<int, double> rmse;
    for (int m : {2, 4, 8, 16}) {
        const Scene s = localized(scene, m);
        GpuRenderer gpu(s, plan_features(s), fresnel, nullptr);
        gpu.capture_environment();
        rmse[m] = sphere_errors(gpu.render(), mc.render, 1)[0].rmse;
        std::printf("localized M = %2d: RMSE %.5f against the Monte-Carlo reference (its noise %.5f)\n", m, rmse[m],
                    noise);
    }
    EXPECT_GT(rmse[2], rmse[4]);
    EXPECT_GT(rmse[4], rmse[8]);
    // From M = 8 on the error is the reference's noise: sqrt(bias² + noise²) within 15 % of the noise.
    EXPECT_LT(rmse[8], 1.15 * noise);
    EXPECT_LT(rmse[16], 1.15 * noise);
    GpuRenderer gpu(scene, plan_features(scene), fresnel, nullptr);
    gpu.capture_environment();
    const double prefiltered = sphere_errors(gpu.render(), mc.render, 1)[0].rmse;
    std::printf("prefiltered (classic lookup): RMSE %.5f\n", prefiltered);
    EXPECT_GT(prefiltered, rmse[16]);
}

}  // namespace test_preview_glossy
}  // namespace metalfit::glpreview
