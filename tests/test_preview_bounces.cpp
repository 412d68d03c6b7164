// Inter-reflections in the CPU references (issue 34, items 2 and 3): max_bounces = 1 is the one-bounce reference,
// paths between two mirrors against an independent tracer, gold in gold turning redder bounce by bounce, the spectral
// reference (grey light at one bounce is the RGB reference curve; the uplift reproduces RGB), the Monte-Carlo
// reference's bounces in the mirror limit, and metrics.json's bounce_orders only when max_bounces > 1.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <numeric>

#include "glpreview/gl/gl_context.hpp"
#include "glpreview/render/bounce_orders.hpp"
#include "glpreview/render/bounces_bench.hpp"
#include "glpreview/render/cpu_reference.hpp"
#include "glpreview/render/environment.hpp"
#include "glpreview/render/mirror_path.hpp"
#include "glpreview/render/monte_carlo_reference.hpp"
#include "glpreview/render/preview.hpp"
#include "glpreview/render/rgb_uplift.hpp"
#include "glpreview/render/spectral_fresnel.hpp"
#include "glpreview/render/spectral_reference.hpp"
#include "glpreview/scene/camera.hpp"
#include "libfit/color/color_space.hpp"
#include "libfit/models/model.hpp"
#include "libfit/reference/reference_curve.hpp"
#include "test_support.hpp"

namespace metalfit::glpreview {
namespace test_preview_bounces {

using test::kData;

FresnelLibrary& library() {
    static FresnelLibrary lib(kData, choose_ocio_config(std::nullopt, kData), "", "bounces.json");
    return lib;
}

const SphereFresnel& fresnel_of(const std::string& material, const std::string& model = "reference") {
    Sphere s;
    s.material = material;
    if (model != "reference") s.fresnel = ModelFresnel{model, ParameterSource::fit};
    return library().get(s, "spheres[0]");
}

// A Fresnel linear in μ, a + (b − a) μ per channel: a two-entry table, which the CPU evaluates exactly.
SphereFresnel linear_fresnel(RGB a, RGB b) {
    SphereFresnel f;
    f.lut = {a, b};
    return f;
}

// Two spheres side by side 0.1 apart in the default (coloured) room, seen from the front.
Scene facing_spheres(int width = 96, int height = 64) {
    Scene scene;
    scene.file = "bounces.json";
    scene.width = width;
    scene.height = height;
    scene.camera.position = {0, 1.1, 2.6};
    scene.camera.look_at = {0, 1.0, 0};
    scene.camera.fov_y_deg = 40;
    for (double x : {-0.55, 0.55}) {
        Sphere s;
        s.center = {x, 1.0, 0};
        s.radius = 0.5;
        s.reflection = ReflectionMode::classic;
        scene.spheres.push_back(s);
    }
    return scene;
}

// A sphere room of one grey: every direction sees the same radiance.
void grey_light(Scene& scene, double grey) {
    scene.environment.type = EnvironmentType::sphere_room;
    scene.environment.sphere_room.light = scene.environment.sphere_room.dark = RGB{grey, grey, grey};
    scene.environment.reference_point = Vec3{0, 1, 0};
}

// The test's own tracer: the nearest sphere by projecting its centre on the ray (not the quadratic formula of the
// renderer), and the mirror path through up to `bounces` reflections.
struct OwnHit {
    int sphere = -1;
    double t = 0;
};
OwnHit own_hit(const std::vector<Sphere>& spheres, Vec3 o, Vec3 d, int skip) {
    OwnHit best;
    double best_t = 1e300;
    for (std::size_t i = 0; i < spheres.size(); ++i) {
        if (static_cast<int>(i) == skip) continue;
        const Vec3 to_centre = spheres[i].center - o;
        const double along = dot(to_centre, d);
        const double miss2 = dot(to_centre, to_centre) - along * along;
        const double r2 = spheres[i].radius * spheres[i].radius;
        if (miss2 > r2) continue;
        const double t = along - std::sqrt(r2 - miss2);
        if (t > 1e-9 && t < best_t) best_t = t, best = {static_cast<int>(i), t};
    }
    return best;
}

struct OwnPath {
    std::vector<std::pair<int, double>> bounces;  // sphere, μ
    Vec3 origin, direction;
};
OwnPath own_path(const Scene& scene, int px, int py, int bounces) {
    const CameraBasis basis = camera_basis(scene.camera, scene.width, scene.height);
    Vec3 o = basis.position, d = camera_ray(basis, px, py, scene.width, scene.height);
    OwnPath path;
    int skip = -1;
    for (int k = 0; k < bounces; ++k) {
        const OwnHit hit = own_hit(scene.spheres, o, d, skip);
        if (hit.sphere < 0) break;
        const Sphere& s = scene.spheres[static_cast<std::size_t>(hit.sphere)];
        const Vec3 p = o + hit.t * d;
        const Vec3 n = normalize(p - s.center);
        const double mu = -dot(d, n);
        path.bounces.emplace_back(hit.sphere, std::clamp(mu, 0.0, 1.0));
        d = normalize(d + 2 * mu * n);
        o = p;
        skip = hit.sphere;
    }
    path.origin = o;
    path.direction = d;
    return path;
}

double relative(double a, double b) { return std::abs(a - b) / std::max(std::abs(b), 1e-6); }

TEST(PreviewBounces, OneBounceIsTheOneBounceReferenceBitForBit) {
    // max_bounces = 1 (the default argument) against the one-bounce reference's own arithmetic, written out here: the
    // nearest sphere, F(μ) times the environment along the reflected ray. The other sphere is never seen in a mirror.
    const Scene scene = facing_spheres();
    const SphereFresnel gold = linear_fresnel({0.6, 0.4, 0.1}, {1, 1, 1});
    const SphereFresnel copper = linear_fresnel({0.5, 0.2, 0.1}, {1, 1, 1});
    const std::vector<const SphereFresnel*> f{&gold, &copper};
    const EnvironmentTracer tracer(scene.environment);
    const ReferenceRender by_default = render_reference(scene, f, tracer, 2);
    const ReferenceRender one = render_reference(scene, f, tracer, 2, nullptr, 1);
    EXPECT_EQ(by_default.image.rgb, one.image.rgb);
    const CameraBasis basis = camera_basis(scene.camera, scene.width, scene.height);
    for (int py = 0; py < scene.height; ++py)
        for (int px = 0; px < scene.width; ++px) {
            const Vec3 d = camera_ray(basis, px, py, scene.width, scene.height);
            int nearest = -1;
            double t_nearest = std::numeric_limits<double>::infinity();
            for (std::size_t s = 0; s < scene.spheres.size(); ++s) {
                const Vec3 oc = basis.position - scene.spheres[s].center;
                const double b = dot(oc, d);
                const double disc = b * b - (dot(oc, oc) - 0.25);
                if (disc < 0) continue;
                const double t = -b - std::sqrt(disc);
                if (t > 0 && t < t_nearest) t_nearest = t, nearest = static_cast<int>(s);
            }
            RGB expected = tracer.trace(basis.position, d).radiance;
            if (nearest >= 0) {
                const Sphere& sphere = scene.spheres[static_cast<std::size_t>(nearest)];
                const Vec3 p = basis.position + t_nearest * d;
                const Vec3 n = (1.0 / sphere.radius) * (p - sphere.center);
                const double mu = std::clamp(-dot(d, n), 0.0, 1.0);
                expected =
                    (*f[static_cast<std::size_t>(nearest)])(mu)*tracer.trace(p, normalize(reflect(d, n))).radiance;
            }
            const int row = scene.height - 1 - py;
            const RGB got = one.image.at(px, row);
            for (int c = 0; c < 3; ++c) ASSERT_EQ(float(got[c]), float(expected[c])) << px << "," << py;
            ASSERT_EQ(one.sphere_id[static_cast<std::size_t>(row) * scene.width + px], nearest);
        }
}

TEST(PreviewBounces, TwoMirrorsFacingEachOtherMultiplyEachBouncesFresnelAgainstAnIndependentTracer) {
    const Scene scene = facing_spheres();
    const SphereFresnel a = linear_fresnel({0.7, 0.5, 0.2}, {1, 1, 1});
    const SphereFresnel b = linear_fresnel({0.3, 0.6, 0.9}, {1, 1, 1});
    const std::vector<const SphereFresnel*> f{&a, &b};
    const EnvironmentTracer tracer(scene.environment);
    for (int bounces : {2, 3}) {
        const ReferenceRender image = render_reference(scene, f, tracer, 2, nullptr, bounces);
        int reaching = 0;
        for (int py = 0; py < scene.height; ++py)
            for (int px = 0; px < scene.width; ++px) {
                const OwnPath path = own_path(scene, px, py, bounces);
                if (path.bounces.empty()) continue;
                RGB expected = tracer.trace(path.origin, path.direction).radiance;
                for (const auto& [sphere, mu] : path.bounces) {
                    const double x = mu;  // the linear Fresnel, evaluated here by hand
                    const RGB lo = sphere == 0 ? RGB{0.7, 0.5, 0.2} : RGB{0.3, 0.6, 0.9};
                    expected = expected * RGB{lo.r + x * (1 - lo.r), lo.g + x * (1 - lo.g), lo.b + x * (1 - lo.b)};
                }
                if (static_cast<int>(path.bounces.size()) == bounces) ++reaching;
                const RGB got = image.image.at(px, scene.height - 1 - py);
                for (int c = 0; c < 3; ++c)
                    ASSERT_LT(relative(got[c], expected[c]), 2e-6)
                        << bounces << " bounces, pixel " << px << "," << py << " channel " << c;
            }
        // The test reaches the paths it is about: many pixels see the other sphere (and, at 3, themselves again).
        EXPECT_GT(reaching, bounces == 2 ? 80 : 10) << bounces;
    }
}

TEST(PreviewBounces, GoldSeenInGoldTurnsRedderBounceByBounce) {
    // Two gold mirrors under grey light: where a path reaches k bounces the pixel is L · Π F_Au(μ_i), and its red to
    // blue ratio grows with every bounce.
    Scene scene = facing_spheres();
    grey_light(scene, 0.5);
    const SphereFresnel& gold = fresnel_of("Au");
    const std::vector<const SphereFresnel*> f{&gold, &gold};
    const EnvironmentTracer tracer(scene.environment);
    std::vector<ReferenceRender> orders;
    for (int k = 1; k <= 3; ++k) orders.push_back(render_reference(scene, f, tracer, 2, nullptr, k));
    int checked = 0;
    for (int py = 0; py < scene.height; ++py)
        for (int px = 0; px < scene.width; ++px) {
            if (own_path(scene, px, py, 3).bounces.size() != 3) continue;
            const int row = scene.height - 1 - py;
            double previous = 0;
            for (const ReferenceRender& image : orders) {
                const RGB c = image.image.at(px, row);
                const double ratio = c.r / c.b;
                EXPECT_GT(ratio, previous * (1 + 1e-4)) << px << "," << py;
                previous = ratio;
            }
            ++checked;
        }
    EXPECT_GT(checked, 20);
}

TEST(PreviewBounces, TheUpliftReproducesRgbAndKeepsGreyFlat) {
    const RgbUplift uplift(library().colorimetry(), library().converter());
    const std::vector<double> flat(uplift.size(), 1.0);
    for (const RGB& light :
         {RGB{1, 0, 0}, RGB{0, 1, 0}, RGB{0, 0, 1}, RGB{0.65, 0.2, 0.15}, RGB{6, 6, 6}, RGB{0.02, 0.5, 3.0}}) {
        const RGB back = uplift.rgb(flat, light);
        const RGB again = uplift.rgb_of(uplift.spectrum(light));
        for (int c = 0; c < 3; ++c) {
            EXPECT_NEAR(back[c], light[c], 1e-6 * std::max(1.0, light[c])) << c;
            EXPECT_NEAR(again[c], light[c], 1e-6 * std::max(1.0, light[c])) << c;
        }
    }
    // Σ_c b_c ≡ 1 (grey light is spectrally flat), and the basis is smooth: no step between neighbouring nanometres
    // larger than a sigmoid of 15 nm scale allows.
    for (std::size_t i = 0; i < uplift.size(); ++i) {
        EXPECT_NEAR(uplift.basis(0)[i] + uplift.basis(1)[i] + uplift.basis(2)[i], 1.0, 1e-6) << i;
        for (int c = 0; c < 3 && i > 0; ++c)
            EXPECT_LT(std::abs(uplift.basis(c)[i] - uplift.basis(c)[i - 1]), 0.2) << c << " at " << i;
    }
}

TEST(PreviewBounces, TheSpectralReferenceOfGreyLightAtOneBounceIsTheRgbReferenceCurve) {
    Scene scene = facing_spheres(64, 40);
    grey_light(scene, 0.5);
    Sphere au;
    au.material = "Au";
    Sphere cu;
    cu.material = "Cu";
    const Material gold = library().material(au, "spheres[0]"), copper = library().material(cu, "spheres[1]");
    const SpectralFresnel gold_spectral(gold, library().colorimetry()),
        copper_spectral(copper, library().colorimetry());
    const ReferenceCurve gold_curve(gold, library().colorimetry(), library().converter());
    const ReferenceCurve copper_curve(copper, library().colorimetry(), library().converter());
    const RgbUplift uplift(library().colorimetry(), library().converter());
    const EnvironmentTracer tracer(scene.environment);
    const ReferenceRender spectral =
        render_spectral_reference(scene, {&gold_spectral, &copper_spectral}, uplift, tracer, 1, 2);
    const std::vector<const SphereFresnel*> luts{&fresnel_of("Au"), &fresnel_of("Cu")};
    const ReferenceRender rgb = render_reference(scene, luts, tracer, 2, nullptr, 1);
    int spheres = 0;
    for (int py = 0; py < scene.height; ++py)
        for (int px = 0; px < scene.width; ++px) {
            const OwnPath path = own_path(scene, px, py, 1);
            if (path.bounces.empty()) continue;
            const auto [sphere, mu] = path.bounces.front();
            const RGB curve = 0.5 * (sphere == 0 ? gold_curve(mu) : copper_curve(mu));
            const RGB got = spectral.image.at(px, scene.height - 1 - py);
            const RGB lut = rgb.image.at(px, scene.height - 1 - py);
            for (int c = 0; c < 3; ++c) {
                ASSERT_LT(relative(got[c], curve[c]), 1e-6) << px << "," << py << " channel " << c;
                ASSERT_LT(relative(got[c], lut[c]), 2e-4) << px << "," << py << " channel " << c;  // the LUT's steps
            }
            ++spheres;
        }
    EXPECT_GT(spheres, 500);
    // At two bounces grey light still gives the product of the curves only where it is one bounce: the
    // spectral product differs from the RGB one where a path reaches the other sphere (the RGB rendering's error).
    const ReferenceRender spectral2 =
        render_spectral_reference(scene, {&gold_spectral, &copper_spectral}, uplift, tracer, 2, 2);
    const ReferenceRender rgb2 = render_reference(scene, luts, tracer, 2, nullptr, 2);
    double largest = 0;
    for (int py = 0; py < scene.height; ++py)
        for (int px = 0; px < scene.width; ++px)
            if (own_path(scene, px, py, 2).bounces.size() == 2) {
                const RGB s = spectral2.image.at(px, scene.height - 1 - py);
                const RGB r = rgb2.image.at(px, scene.height - 1 - py);
                for (int c = 0; c < 3; ++c) largest = std::max(largest, relative(r[c], s[c]));
            }
    EXPECT_GT(largest, 1e-3);  // gold × copper: the product of the RGB curves is not the RGB of the product
}

TEST(PreviewBounces, MonteCarloBouncesTendToTheMirrorPathsAsRoughnessGoesToZero) {
    // A rough sphere of roughness 0.02 facing a mirror: the Monte-Carlo reference with 3 bounces estimates the
    // mirror's pixels whose path reaches the rough sphere too, and agrees with the analytic 3-bounce reference
    // (which treats the rough sphere as a mirror) within a few per cent; with 1 bounce the mirror keeps its pixels.
    Scene scene = facing_spheres(48, 32);
    scene.spheres[1].roughness = 0.02;
    const SphereFresnel& gold = fresnel_of("Au");
    const SphereFresnel& copper = fresnel_of("Cu");
    const std::vector<const SphereFresnel*> f{&gold, &copper};
    const EnvironmentTracer tracer(scene.environment);
    const ReferenceRender analytic = render_reference(scene, f, tracer, 2, nullptr, 3);
    const MonteCarloReference mc = render_monte_carlo_reference(scene, f, tracer, analytic, 64, 2, nullptr, 3);
    const ReferenceRender analytic1 = render_reference(scene, f, tracer, 2, nullptr, 1);
    const MonteCarloReference mc1 = render_monte_carlo_reference(scene, f, tracer, analytic1, 64, 2, nullptr, 1);
    double error = 0, total = 0;
    int mirror_pixels_estimated = 0;
    for (std::size_t p = 0; p < analytic.sphere_id.size(); ++p) {
        if (analytic.sphere_id[p] < 0) continue;
        if (analytic.sphere_id[p] == 0) {
            if (mc.standard_error.rgb[3 * p] > 0) ++mirror_pixels_estimated;
            EXPECT_EQ(mc1.standard_error.rgb[3 * p], 0.0f);  // one bounce: the mirror's pixels are the analytic ones
        }
        for (int c = 0; c < 3; ++c) {
            const double d = double(mc.render.image.rgb[3 * p + c]) - analytic.image.rgb[3 * p + c];
            error += d * d;
            total += double(analytic.image.rgb[3 * p + c]) * analytic.image.rgb[3 * p + c];
        }
    }
    EXPECT_GT(mirror_pixels_estimated, 10);
    EXPECT_LT(std::sqrt(error / total), 0.05);
}

// A preview of two spheres facing each other (GL: llvmpipe in CI), its metrics.json.
nlohmann::ordered_json preview_metrics(int max_bounces) {
    std::string json = R"({"image": {"width": 48, "height": 32}, "environment": {"cube_size": 64},
        "camera": {"position": [0, 1.1, 2.6], "look_at": [0, 1.0, 0], "fov_y_deg": 40},
        "spheres": [{"center": [-0.55, 1.0, 0], "radius": 0.5, "material": "Au", "reflection": "classic"},
                    {"center": [0.55, 1.0, 0], "radius": 0.5, "material": "Cu", "fresnel": "schlick",
                     "reflection": "classic"}],
        "outputs": {"png": false})";
    if (max_bounces > 0) json += R"(, "max_bounces": )" + std::to_string(max_bounces);
    const Scene scene = parse_scene(json + "}", "bounces.json");
    static GlContext context = GlContext::create();
    const PreviewOptions options{kData, choose_ocio_config(std::nullopt, kData), {}, 2};
    return run_preview(scene, options, &context).metrics;
}

TEST(PreviewBounces, MetricsJsonHasBounceOrdersOnlyAboveOneBounce) {
    using Json = nlohmann::ordered_json;
    const Json absent = preview_metrics(0);
    const Json one = preview_metrics(1);
    for (const Json& j : {absent, one})
        for (const Json& s : j["spheres"]) EXPECT_FALSE(s.contains("bounce_orders"));
    EXPECT_EQ(absent.dump(), one.dump());
    const Json three = preview_metrics(3);
    for (const Json& s : three["spheres"]) {
        ASSERT_TRUE(s.contains("bounce_orders"));
        ASSERT_EQ(s["bounce_orders"].size(), 3u);
        for (int k = 0; k < 3; ++k) {
            const Json& order = s["bounce_orders"][static_cast<std::size_t>(k)];
            EXPECT_EQ(order["order"], k + 1);
            for (const char* key : {"model", "rgb_vs_spectral", "model_vs_spectral"})
                for (const char* metric : {"rmse", "de2000_mean", "de2000_p95"})
                    EXPECT_TRUE(order[key][metric].is_number()) << key << "." << metric;
        }
    }
    // The gold sphere shows the reference: its model error at one bounce is 0, at two it is the copper schlick it
    // sees; the copper's model error is that of schlick from the first bounce on.
    const Json& gold = three["spheres"][0]["bounce_orders"];
    EXPECT_EQ(gold[0]["model"]["rmse"].get<double>(), 0.0);
    EXPECT_GT(gold[1]["model"]["rmse"].get<double>(), 0.0);
    EXPECT_GT(three["spheres"][1]["bounce_orders"][0]["model"]["rmse"].get<double>(), 0.0);
}

TEST(PreviewBounces, TheBenchTableHasEveryModelAtEveryOrder) {
    const PreviewOptions options{kData, choose_ocio_config(std::nullopt, kData), {}, 2};
    const nlohmann::ordered_json result = bench_bounces(options, true);
    ASSERT_EQ(result["rgb_vs_spectral"].size(), static_cast<std::size_t>(kBenchBounceOrders));
    const std::size_t rows = result["rows"].size() + kBenchBounceOrders * result["skipped"].size();
    EXPECT_EQ(rows, all_models().size() * 2 * kBenchBounceOrders);
    for (const auto& r : result["rows"]) {
        EXPECT_TRUE(r["rmse"].is_number());
        EXPECT_GT(r["reaching"]["pixels"].get<int>(), 0);
    }
    // The RGB rendering's own error grows where paths compound: the k-bounce pixels' p95 at 4 bounces is above
    // that at 1.
    const auto& rgb = result["rgb_vs_spectral"];
    EXPECT_GT(rgb[0]["de2000_p95"].get<double>(), 0.0);
    EXPECT_GT(rgb[3]["reaching"]["de2000_p95"].get<double>(), rgb[0]["reaching"]["de2000_p95"].get<double>());
}

}  // namespace test_preview_bounces
}  // namespace metalfit::glpreview
