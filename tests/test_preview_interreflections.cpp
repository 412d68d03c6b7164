// The inter-reflections effect (max_bounces): its scene key and bad input, its plan (which spheres get a distance
// map, from the geometry), the cube-face views of its maps, and the GPU frame against paths traced here with exact
// ray–sphere intersections: spheres seen in spheres, bounce by bounce.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <optional>
#include <string>

#include "effects/interreflections/bounce_maps.hpp"
#include "effects/interreflections/bounce_plan.hpp"
#include "glpreview/effects/bounces.hpp"
#include "glpreview/render/environment.hpp"
#include "glpreview/render/plan.hpp"
#include "glpreview/render/preview.hpp"
#include "glpreview/scene/camera.hpp"
#include "libfit/base/errors.hpp"
#include "libfit/color/color_space.hpp"
#include "test_support.hpp"

namespace metalfit::glpreview {
namespace test_preview_interreflections {

using test::kData;

// Two mirror spheres side by side (gold, copper) and a third behind them (silver), in a room of plain coloured
// surfaces (one check per surface, no panels), so that a pixel's path is smooth across it, seen close up.
std::string facing_scene(const std::string& bounces, const std::string& third = "", int width = 160, int height = 120) {
    return R"({"image": {"width": )" + std::to_string(width) + R"(, "height": )" + std::to_string(height) + R"(},
      "camera": {"position": [0.0, 0.9, 1.7], "look_at": [0.0, 0.6, 0.0], "fov_y_deg": 40},
      "environment": {"type": "room", "reference_point": [0, 1.2, 0], "panels": [], "checker": 100,
                      "ceiling": [0.9, 0.9, 0.9], "floor_light": [0.5, 0.5, 0.5]},)" +
           bounces + R"(
      "spheres": [
        {"center": [-0.55, 0.6, 0.0], "radius": 0.45, "material": "Au"},
        {"center": [0.55, 0.6, 0.0], "radius": 0.45, "material": "Cu"})" +
           third + R"(],
      "outputs": {"png": false, "reference": false, "difference": false, "metrics": false}})";
}

std::string parse_error(const std::string& json) {
    try {
        parse_scene(json, "bounces.json");
    } catch (const InputError& e) {
        return e.what();
    }
    return "";
}

TEST(InterreflectionsScene, MaxBouncesIsReadAndDefaultsToOne) {
    EXPECT_EQ(max_bounces(parse_scene(facing_scene(""), "bounces.json")), 1);
    EXPECT_EQ(max_bounces(parse_scene(facing_scene(R"("max_bounces": 4,)"), "bounces.json")), 4);
}

TEST(InterreflectionsScene, BadInputNamesTheField) {
    EXPECT_TRUE(test::Contains(parse_error(facing_scene(R"("max_bounces": 0,)")), "max_bounces: must be in [1, 8]"));
    EXPECT_TRUE(test::Contains(parse_error(facing_scene(R"("max_bounces": 9,)")), "max_bounces: must be in [1, 8]"));
    EXPECT_TRUE(
        test::Contains(parse_error(facing_scene(R"("max_bounces": 2.5,)")), "max_bounces: expected an integer"));
    const std::string overlapping =
        facing_scene(R"("max_bounces": 2,)", R"(, {"center": [0.1, 0.6, 0.2], "radius": 0.3, "material": "Ag"})");
    EXPECT_TRUE(test::Contains(parse_error(overlapping), "bounces.json: spheres[2]: overlaps spheres[0]"))
        << parse_error(overlapping);
    // Overlapping spheres stay allowed with one bounce (they do not reflect each other).
    EXPECT_EQ(parse_error(facing_scene("", R"(, {"center": [0.1, 0.6, 0.2], "radius": 0.3, "material": "Ag"})")), "");
    const std::string at_infinity = R"({"environment": {"type": "equirect", "file": "sky.hdr"}, "max_bounces": 2,
        "spheres": [{"center": [0, 1, 0], "radius": 0.5, "reflection": "classic"}]})";
    EXPECT_TRUE(test::Contains(parse_error(at_infinity), "max_bounces: inter-reflections need a captured environment"));
    std::string many = R"({"max_bounces": 2, "spheres": [)";
    for (int i = 0; i < 17; ++i)
        many += (i ? ", " : "") + std::string(R"({"center": [)") + std::to_string(-2.4 + 0.3 * i) +
                R"(, 1, 0], "radius": 0.1})";
    many += "]}";
    EXPECT_TRUE(
        test::Contains(parse_error(many), "max_bounces: at most 16 mirror spheres reflect each other (17 here)"))
        << parse_error(many);
}

TEST(InterreflectionsScene, AMirrorSearchesItsOwnMapWhateverLookupItAskedFor) {
    std::string json = facing_scene(R"("max_bounces": 2,)");
    json.replace(json.find(R"("material": "Au")"), 16, R"("material": "Au", "reflection": "classic")");
    const Scene scene = parse_scene(json, "bounces.json");
    EXPECT_EQ(scene.spheres[0].reflection, ReflectionMode::distance_impostor);
    ASSERT_FALSE(scene.warnings.empty());
    EXPECT_TRUE(test::Contains(scene.warnings.front(), "spheres[0].reflection: 'classic' becomes 'distance-impostor'"));
    // With one bounce the lookup is the scene's.
    std::string one = facing_scene("");
    one.replace(one.find(R"("material": "Au")"), 16, R"("material": "Au", "reflection": "classic")");
    EXPECT_EQ(parse_scene(one, "bounces.json").spheres[0].reflection, ReflectionMode::classic);
}

TEST(InterreflectionsPlan, MapsComeFromTheGeometry) {
    const Scene one = parse_scene(facing_scene(""), "bounces.json");
    EXPECT_FALSE(plan_bounces(one).active());
    EXPECT_FALSE(build_plan(one).runs("sphere-maps"));

    const Scene three = parse_scene(facing_scene(R"("max_bounces": 3,)"), "bounces.json");
    const BouncePlan plan = plan_bounces(three);
    EXPECT_EQ(plan.mapped, (std::vector<std::size_t>{0, 1}));
    const Plan graph = build_plan(three);
    EXPECT_TRUE(graph.runs("sphere-maps"));
    const std::string text = explain(graph, three);
    EXPECT_TRUE(test::Contains(text, "sphere-maps [GPU]: max_bounces 3: mirror sphere 0 sees 1; 1 sees 0")) << text;
    EXPECT_TRUE(test::Contains(text, "up to 3 reflections")) << text;

    // A lone sphere has nothing to reflect; a rough sphere gets a prefiltered map of its own (and is seen in the
    // mirror's).
    const Scene lone =
        parse_scene(R"({"max_bounces": 3, "spheres": [{"center": [0, 1, 0], "radius": 0.5}]})", "b.json");
    EXPECT_FALSE(plan_bounces(lone).active());
    EXPECT_TRUE(test::Contains(explain(build_plan(lone), lone), "no sphere sees another sphere (one sphere)"));
    std::string rough = facing_scene(R"("max_bounces": 2,)");
    rough.replace(rough.find(R"("material": "Cu")"), 16, R"("material": "Cu", "roughness": 0.3)");
    const BouncePlan with_rough = plan_bounces(parse_scene(rough, "bounces.json"));
    EXPECT_EQ(with_rough.mapped, (std::vector<std::size_t>{0}));
    EXPECT_EQ(with_rough.rough_mapped, (std::vector<std::size_t>{1}));

    // A column between two spheres hides each from the other: no map.
    const Scene walled = parse_scene(R"({"max_bounces": 2, "environment": {"type": "room",
        "columns": [{"center": [0, 0], "half_width": 0.6}]},
        "spheres": [{"center": [-1.5, 1, 0], "radius": 0.4}, {"center": [1.5, 1, 0], "radius": 0.4}]})",
                                     "b.json");
    EXPECT_TRUE(hidden_by_room(walled, walled.spheres[0], walled.spheres[1]));
    EXPECT_FALSE(plan_bounces(walled).active());
    const Scene open = parse_scene(facing_scene(R"("max_bounces": 2,)"), "bounces.json");
    EXPECT_FALSE(hidden_by_room(open, open.spheres[0], open.spheres[1]));
}

// The map's faces are drawn with camera_ray(): every texel's ray must be the direction OpenGL's cube-map face
// selection gives that texel (the cube_direction() of the capture).
TEST(InterreflectionsMaps, EachFaceViewRaysMatchTheCubeTexels) {
    const int n = 8;
    const Vec3 centre{0.3, -0.2, 1.1};
    for (int face = 0; face < 6; ++face) {
        const CameraBasis view = cube_face_view(centre, face);
        for (int py = 0; py < n; ++py)
            for (int px = 0; px < n; ++px) {
                const Vec3 d = camera_ray(view, px, py, n, n);
                // The face OpenGL selects: the major axis and its sign; the face coordinates (s, t) per its table.
                const double ax = std::abs(d.x), ay = std::abs(d.y), az = std::abs(d.z);
                int selected;
                double s, t;
                if (ax >= ay && ax >= az) {
                    selected = d.x > 0 ? 0 : 1;
                    s = (d.x > 0 ? -d.z : d.z) / ax;
                    t = -d.y / ax;
                } else if (ay >= az) {
                    selected = d.y > 0 ? 2 : 3;
                    s = d.x / ay;
                    t = d.y > 0 ? d.z / ay : -d.z / ay;
                } else {
                    selected = d.z > 0 ? 4 : 5;
                    s = (d.z > 0 ? d.x : -d.x) / az;
                    t = -d.y / az;
                }
                EXPECT_EQ(selected, face);
                // Texel (px, py) of a face covers s, t = 2 (p + 1/2) / n − 1 (rows from t = −1, as GL stores them).
                EXPECT_NEAR(s, 2.0 * (px + 0.5) / n - 1, 1e-12) << face;
                EXPECT_NEAR(t, 2.0 * (py + 0.5) / n - 1, 1e-12) << face;
            }
    }
}

// Paths traced here, independently of the renderer: the nearest sphere along a ray, mirror reflection, the next
// sphere (not the one left), up to `bounces` reflections, then the environment.
struct Traced {
    RGB radiance{0, 0, 0};
    int reflections = 0;      // 0: the camera ray missed every sphere
    double closest_edge = 1;  // the smallest |sin| of the angle between a ray and a sphere's silhouette along the path
};

std::optional<double> hit_sphere(const Sphere& s, Vec3 o, Vec3 d) {
    const Vec3 oc = o - s.center;
    const double b = dot(oc, d), h = b * b - (dot(oc, oc) - s.radius * s.radius);
    if (h < 0) return std::nullopt;
    const double t = -b - std::sqrt(h);
    return t > 1e-9 ? std::optional<double>(t) : std::nullopt;
}

Traced trace_path(const Scene& scene, const std::vector<const SphereFresnel*>& fresnel,
                  const EnvironmentTracer& environment, Vec3 o, Vec3 d, int bounces) {
    Traced out;
    RGB throughput{1, 1, 1};
    int left = -1;
    for (;;) {
        int nearest = -1;
        double t_best = 1e30;
        for (std::size_t i = 0; i < scene.spheres.size(); ++i) {
            if (static_cast<int>(i) == left) continue;
            const auto t = hit_sphere(scene.spheres[i], o, d);
            if (t && *t < t_best) {
                t_best = *t;
                nearest = static_cast<int>(i);
            }
            // How close the ray passes to this sphere's silhouette (pixels there straddle two paths).
            const Vec3 oc = scene.spheres[i].center - o;
            const double along = dot(oc, d);
            if (along > 0 && static_cast<int>(i) != left) {
                const double miss = std::sqrt(std::max(dot(oc, oc) - along * along, 0.0));
                out.closest_edge = std::min(out.closest_edge, std::abs(miss - scene.spheres[i].radius) / length(oc));
            }
        }
        if (nearest < 0 || out.reflections == bounces) {
            const RGB l = environment.trace(o, d).radiance;
            out.radiance = {throughput.r * l.r, throughput.g * l.g, throughput.b * l.b};
            return out;
        }
        const Vec3 p = o + t_best * d;
        const Vec3 n = normalize(p - scene.spheres[nearest].center);
        const double mu = std::clamp(-dot(d, n), 0.0, 1.0);
        const RGB f = (*fresnel[nearest])(mu);
        throughput = {throughput.r * f.r, throughput.g * f.g, throughput.b * f.b};
        d = d - 2 * dot(d, n) * n;
        o = p;
        left = nearest;
        ++out.reflections;
    }
}

PreviewOptions options() { return {kData, choose_ocio_config(std::nullopt, kData), {}, 0}; }

FresnelLibrary& library() {
    static FresnelLibrary lib(kData, choose_ocio_config(std::nullopt, kData), "", "bounces.json");
    return lib;
}

struct Agreement {
    double share = 0;  // of the pixels with ≥ 2 reflections at `bounces` (away from silhouettes) within tolerance
    int pixels = 0;
};

// The GPU frame of the scene at max_bounces `rendered` against paths traced to `traced` reflections.
Agreement agreement(const std::string& json, int rendered, int traced, double tolerance) {
    Scene scene = parse_scene(json, "bounces.json");
    if (rendered > 1) scene.effects.set(Interreflections{rendered});
    std::vector<const SphereFresnel*> fresnel;
    for (std::size_t i = 0; i < scene.spheres.size(); ++i)
        fresnel.push_back(&library().get(scene.spheres[i], "spheres[" + std::to_string(i) + "]"));
    const PreviewResult result = run_preview(scene, options());
    const EnvironmentTracer environment(scene.environment);
    const CameraBasis basis = camera_basis(scene.camera, scene.width, scene.height);
    Agreement a;
    int agree = 0;
    for (int py = 0; py < scene.height; ++py)
        for (int px = 0; px < scene.width; ++px) {
            const Traced path = trace_path(scene, fresnel, environment, basis.position,
                                           camera_ray(basis, px, py, scene.width, scene.height), traced);
            if (path.reflections < 2 || path.closest_edge < 0.02) continue;
            const RGB gpu = result.beauty->at(px, scene.height - 1 - py);
            const double error = std::max({std::abs(gpu.r - path.radiance.r), std::abs(gpu.g - path.radiance.g),
                                           std::abs(gpu.b - path.radiance.b)});
            ++a.pixels;
            if (error < tolerance) ++agree;
        }
    a.share = a.pixels ? double(agree) / a.pixels : 0;
    return a;
}

TEST(InterreflectionsGpu, SpheresSeenInSpheresAgreeWithTracedPaths) {
    const std::string json = facing_scene("", "", 160, 120);
    const Agreement two = agreement(json, 2, 2, 0.03);
    ASSERT_GT(two.pixels, 80);
    EXPECT_GT(two.share, 0.93) << two.pixels << " share " << two.share;
    // The same pixels with one bounce show the room where the other sphere is: most disagree with the traced paths.
    const Agreement one = agreement(json, 1, 2, 0.03);
    EXPECT_LT(one.share, 0.3) << one.pixels << " share " << one.share;
    // Three bounces (with a third sphere behind): the maps' second update.
    const std::string three = facing_scene("", R"(, {"center": [0.0, 0.6, -1.0], "radius": 0.4, "material": "Ag"})");
    const Agreement third = agreement(three, 3, 3, 0.03);
    ASSERT_GT(third.pixels, 80);
    EXPECT_GT(third.share, 0.88) << third.pixels << " share " << third.share;
}

// A rough sphere beside a mirror: with its own prefiltered map it shows the mirror in its lobe, as the Monte-Carlo
// reference (which traces the bounces) does; with one bounce it shows the room there.
TEST(InterreflectionsGpu, ARoughSphereSeesTheMirrorBesideIt) {
    std::string json = facing_scene(R"("max_bounces": 2,)");
    json.replace(json.find(R"("material": "Au")"), 16,
                 R"("material": "Au", "roughness": 0.3, "glossy": "prefiltered")");
    json.replace(json.find(R"("reference": false)"), 18, R"("reference": true, "reference_samples": 64)");
    const Scene scene = parse_scene(json, "bounces.json");
    ASSERT_EQ(plan_bounces(scene).rough_mapped, (std::vector<std::size_t>{0}));
    const PreviewResult two = run_preview(scene, options());
    Scene one = scene;
    one.effects = {};
    const PreviewResult single = run_preview(one, options());
    const ReferenceRender& reference = *two.reference;  // traced to two bounces
    double error_two = 0, error_one = 0;
    int pixels = 0;
    // Over the rough sphere's pixels where the second bounce matters (the two references differ there).
    for (int y = 0; y < scene.height; ++y)
        for (int x = 0; x < scene.width; ++x) {
            if (reference.sphere_id[static_cast<std::size_t>(y) * scene.width + x] != 0) continue;
            const RGB r = reference.image.at(x, y), a = two.beauty->at(x, y), b = single.beauty->at(x, y);
            const RGB r1 = single.reference->image.at(x, y);
            if (std::abs(r.r - r1.r) + std::abs(r.g - r1.g) + std::abs(r.b - r1.b) < 0.1) continue;
            error_two += std::abs(a.r - r.r) + std::abs(a.g - r.g) + std::abs(a.b - r.b);
            error_one += std::abs(b.r - r.r) + std::abs(b.g - r.g) + std::abs(b.b - r.b);
            ++pixels;
        }
    ASSERT_GT(pixels, 100);
    EXPECT_LT(error_two, 0.75 * error_one) << error_two / pixels << " vs " << error_one / pixels;
}

TEST(InterreflectionsGpu, OneBounceIsTodaysFrame) {
    const Scene without = parse_scene(facing_scene(""), "bounces.json");
    const Scene with_one = parse_scene(facing_scene(R"("max_bounces": 1,)"), "bounces.json");
    const PreviewResult a = run_preview(without, options()), b = run_preview(with_one, options());
    ASSERT_TRUE(a.beauty && b.beauty);
    for (int y = 0; y < without.height; ++y)
        for (int x = 0; x < without.width; ++x) {
            const RGB p = a.beauty->at(x, y), q = b.beauty->at(x, y);
            ASSERT_TRUE(p.r == q.r && p.g == q.g && p.b == q.b) << x << "," << y;
        }
}

}  // namespace test_preview_interreflections
}  // namespace metalfit::glpreview
