// The caustics on the GPU (rings and caustics effects): a ring's bad input, the plan (caustic maps only with a ring,
// a light that throws caustics and the room), and the light maps a gold ring's caustic map splats, against photons
// traced here on the CPU with the ring's own intersection and Fresnel (the power that lands) and against the closed
// form of a cylinder mirror's caustic (the cusp at half the radius).
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <numbers>
#include <string>

#include "effects/caustics/caustic_maps.hpp"
#include "effects/caustics/caustic_reference.hpp"
#include "effects/lights/light.hpp"
#include "effects/rings/ring.hpp"
#include "glpreview/effects/registry.hpp"
#include "glpreview/gl/gl_context.hpp"
#include "glpreview/render/gpu_renderer.hpp"
#include "glpreview/render/sphere_fresnel.hpp"
#include "libfit/base/errors.hpp"
#include "libfit/color/color_space.hpp"
#include "test_support.hpp"

namespace metalfit::glpreview {
namespace test_preview_caustics {

using test::kData;

// A gold half ring (its concave side facing +z... the arc's middle at −z) under a grazing directional light
// travelling towards −z, in a room with one sphere far from it.
std::string ring_scene(const std::string& ring = R"("radius": 1.0, "height": 0.35, "arc_deg": 180)",
                       const std::string& lights =
                           R"([{"type": "directional", "direction": [0, -0.35, -1], "intensity": 4, "unit": "W/m2"}])",
                       const std::string& caustics = R"({"map_size": 256, "filter_width": 0.02})") {
    return R"({"image": {"width": 64, "height": 48},
      "environment": {"type": "room", "panels": []},
      "lights": )" +
           lights + R"(,
      "rings": [{"base": [0, 0, 0], "facing_deg": -90, "material": "Au", )" +
           ring + R"(}],
      "caustics": )" +
           caustics + R"(,
      "spheres": [{"center": [2.2, 0.3, 2.2], "radius": 0.3, "material": "Ag"}],
      "outputs": {"png": false, "reference": false, "difference": false, "metrics": false}})";
}

std::string parse_error(const std::string& json) {
    try {
        parse_scene(json, "ring.json");
    } catch (const InputError& e) {
        return e.what();
    }
    return "";
}

TEST(CausticsScene, BadInputNamesTheFileAndField) {
    EXPECT_EQ(parse_error(ring_scene()), "");
    EXPECT_TRUE(
        test::Contains(parse_error(ring_scene(R"("radius": 0, "height": 0.3)")), "rings[0].radius: must be > 0"))
        << parse_error(ring_scene(R"("radius": 0, "height": 0.3)"));
    EXPECT_TRUE(test::Contains(parse_error(ring_scene(R"("radius": -1)")), "rings[0].radius: must be > 0"));
    EXPECT_TRUE(test::Contains(parse_error(ring_scene(R"("arc_deg": 0)")), "rings[0].arc_deg: must be in (0, 360]"));
    EXPECT_TRUE(test::Contains(parse_error(ring_scene(R"("arc_deg": 361)")), "rings[0].arc_deg: must be in (0, 360]"));
    EXPECT_TRUE(test::Contains(parse_error(ring_scene(R"("radius": 3.5)")), "rings[0]: the ring must lie inside"));
    const std::string huge = ring_scene(R"("radius": 1)", R"([])", R"({"map_size": 9000})");
    EXPECT_TRUE(test::Contains(parse_error(huge), "caustics.map_size: must be in [4, 8192]")) << parse_error(huge);
    EXPECT_TRUE(test::Contains(parse_error(huge), "ring.json")) << parse_error(huge);
    EXPECT_TRUE(test::Contains(parse_error(ring_scene(R"("radius": 1)", R"([])", R"({"filter_width": 0})")),
                               "caustics.filter_width: must be > 0"));
}

TEST(CausticsPlan, OnlyARingALightThatThrowsAndTheRoomPlanCausticMaps) {
    EXPECT_EQ(plan_caustics(parse_scene(ring_scene(), "ring.json")).jobs.size(), 1u);
    const CausticPlan dark = plan_caustics(parse_scene(ring_scene(R"("radius": 1)", "[]"), "ring.json"));
    EXPECT_TRUE(dark.jobs.empty());
    EXPECT_EQ(dark.why, "no light");
    // A spot that looks away from the ring, a sphere light: no caustic map.
    const CausticPlan away = plan_caustics(
        parse_scene(ring_scene(R"("radius": 1)",
                               R"([{"type": "spot", "position": [0, 2, 2], "direction": [0, 0, 1], "cone_outer_deg": 20,
                        "cone_inner_deg": 10, "intensity": 5},
                       {"type": "sphere", "position": [0, 2, 0], "radius": 0.1, "intensity": 5}])"),
                    "ring.json"));
    EXPECT_TRUE(away.jobs.empty());
    EXPECT_TRUE(test::Contains(away.why, "light 0 (spot): no ring in its cone")) << away.why;
    EXPECT_TRUE(test::Contains(away.why, "light 1 (sphere): sphere lights throw no caustic")) << away.why;
    // A point light and a spot aimed at the ring: one map each.
    const CausticPlan two =
        plan_caustics(parse_scene(ring_scene(R"("radius": 1)",
                                             R"([{"type": "point", "position": [0, 0.6, 1], "intensity": 5},
                       {"type": "spot", "position": [0, 2, 2], "direction": [0, -1, -1], "intensity": 5}])"),
                                  "ring.json"));
    ASSERT_EQ(two.jobs.size(), 2u);
    EXPECT_EQ(two.jobs[1].light, 1u);
    // Without rings nothing is planned and --explain lists no caustic pass (the scene's passes are today's).
    const Scene plain = parse_scene(R"({"environment": {"type": "room"}, "spheres": [{"center": [0, 1, 0]}],
        "lights": [{"type": "point", "position": [0, 2, 0], "intensity": 1}]})",
                                    "plain.json");
    EXPECT_TRUE(plan_caustics(plain).jobs.empty());
}

// Photons traced on the CPU through the same beam as the GPU's caustic map, with ring.cpp's intersection and the
// ring's Fresnel at every reflection: the power the ring intercepts and the power that leaves it (what lands in the
// room).
struct Traced {
    double intercepted = 0, reflected = 0;
};
Traced traced_power(const Scene& scene, const SphereFresnel& fresnel, int n) {
    const Ring& ring = scene.effects.find<Rings>()->rings[0];
    const Light& light = scene.effects.find<Lights>()->lights[0];
    const Vec3 centre = ring.base + Vec3{0, 0.5 * ring.height, 0};
    const double r = std::hypot(ring.radius, 0.5 * ring.height);
    const Vec3 d = light.direction;
    const Vec3 a = normalize(cross(Vec3{0, 1, 0}, d)), b = cross(d, a);
    const double cell = (2 * r / n) * (2 * r / n);
    Traced total;
    for (int i = 0; i < n; ++i)
        for (int j = 0; j < n; ++j) {
            Vec3 o = centre - (r + 0.5) * d + (-r + (i + 0.5) * 2 * r / n) * a + (-r + (j + 0.5) * 2 * r / n) * b;
            Vec3 dir = d;
            RGB power = (light.intensity * cell) * light.colour;
            int reflections = 0;
            for (; reflections < 16; ++reflections) {
                const auto hit = intersect_ring(ring, o, dir, reflections == 0 ? 0.0 : 1e-9, 1e30);
                if (!hit) break;
                const RGB f = fresnel(-dot(dir, hit->normal));
                power = {power.r * f.r, power.g * f.g, power.b * f.b};
                o = hit->point;
                dir = reflect(dir, hit->normal);
            }
            if (reflections == 0) continue;
            total.intercepted += light.intensity * cell * (light.colour.r + light.colour.g + light.colour.b) / 3;
            total.reflected += (power.r + power.g + power.b) / 3;
        }
    return total;
}

struct CausticFloor {
    std::vector<std::vector<float>> layers;
    double power = 0;  // W over the six faces (mean of the channels)
    Vec3 peak;         // the floor's brightest texel centre
    double texel = 0;  // m
};

CausticFloor gpu_caustic(const Scene& scene) {
    GlContext context = GlContext::create();
    GpuRenderer renderer(scene, plan_features(scene), {}, nullptr);
    const CausticSettings settings = caustic_settings(scene);
    const RoomLightMaps maps = RoomLightMaps::create({settings.light_map_size});
    render_caustic_light_maps(renderer, plan_caustics(scene), settings, maps);
    CausticFloor out;
    out.layers = read_room_light_maps(maps);
    const Room& room = scene.environment.room;
    const double size = maps.size;
    for (int face = 0; face < 6; ++face) {
        const int axis = face / 2, ua = axis == 0 ? 1 : 0, va = axis == 2 ? 1 : 2;
        const double area = (room.max[ua] - room.min[ua]) * (room.max[va] - room.min[va]) / (size * size);
        for (float v : out.layers[static_cast<std::size_t>(face)]) out.power += v * area / 3;
    }
    const std::vector<float>& floor = out.layers[2];  // axis y, the min plane: u along x, v along z
    std::size_t best = 0;
    for (std::size_t t = 0; t < floor.size() / 3; ++t)
        if (floor[3 * t] + floor[3 * t + 1] + floor[3 * t + 2] >
            floor[3 * best] + floor[3 * best + 1] + floor[3 * best + 2])
            best = t;
    const double u = (static_cast<double>(best % maps.size) + 0.5) / size,
                 v = (static_cast<double>(best / maps.size) + 0.5) / size;
    out.peak = {room.min.x + u * (room.max.x - room.min.x), room.min.y, room.min.z + v * (room.max.z - room.min.z)};
    out.texel = (room.max.x - room.min.x) / size;
    return out;
}

Scene resolved(const std::string& json, FresnelLibrary& library) {
    Scene scene = parse_scene(json, "ring.json");
    resolve_effect_materials(scene, library);
    return scene;
}

TEST(CausticsGpu, TheLightMapsHoldThePowerTheRingReflects) {
    FresnelLibrary library(kData, choose_ocio_config(std::nullopt, kData), "", "ring.json");
    const Scene scene = resolved(ring_scene(), library);
    const CausticFloor gpu = gpu_caustic(scene);
    const Traced traced = traced_power(scene, *scene.effects.find<Rings>()->fresnel[0], 1024);
    ASSERT_GT(traced.reflected, 0.5);
    EXPECT_NEAR(gpu.power / traced.reflected, 1.0, 0.02)
        << "GPU " << gpu.power << " W, traced " << traced.reflected << " W";
    // Energy: no more than the light the ring intercepts times its largest reflectance.
    const SphereFresnel& f = *scene.effects.find<Rings>()->fresnel[0];
    double max_f = 0;
    for (int k = 0; k <= 100; ++k) {
        const RGB v = f(k / 100.0);
        max_f = std::max({max_f, v.r, v.g, v.b});
    }
    EXPECT_LE(gpu.power, traced.intercepted * max_f) << traced.intercepted << " W intercepted, max F " << max_f;
}

TEST(CausticsGpu, TheCuspLiesAtHalfTheRadiusAlongTheLight) {
    // A cylinder mirror focuses paraxial parallel light at half its radius (the nephroid's cusp); the light keeps its
    // descent on reflection, so the slice of the wall (R/2)·tan e above the floor lands there (the ring is taller).
    // A narrow arc (30°) reflects paraxial rays only: the brightest floor texel is the cusp. A wide arc's marginal
    // rays cross the axis nearer the mirror (R / (2 cos θ) from the axis): its brightest texel moves towards it.
    FresnelLibrary library(kData, choose_ocio_config(std::nullopt, kData), "", "ring.json");
    const Vec3 cusp{0, 0, -0.5};
    const CausticFloor narrow =
        gpu_caustic(resolved(ring_scene(R"("radius": 1.0, "height": 0.35, "arc_deg": 30)"), library));
    EXPECT_LT(length(narrow.peak - cusp), 0.02 + narrow.texel) << "peak at " << narrow.peak.x << ", " << narrow.peak.z;
    const CausticFloor wide = gpu_caustic(resolved(ring_scene(), library));
    EXPECT_LT(wide.peak.z, narrow.peak.z);
    EXPECT_GT(wide.peak.z, -1.0 / (2 * std::cos(std::numbers::pi / 4)));  // no farther than the 45° rays' crossing
}

TEST(CausticsGpu, ASphereBeforeTheRingShadowsItsCausticAsInTheReference) {
    // A sphere between the grazing light and the ring's wall: on the GPU and in the photon-traced reference its shadow
    // takes the same share of the caustic away.
    FresnelLibrary library(kData, choose_ocio_config(std::nullopt, kData), "", "ring.json");
    std::string shaded = ring_scene(R"("radius": 1.0, "height": 0.35, "arc_deg": 180)",
                                    R"([{"type": "directional", "direction": [0, -0.35, -1], "intensity": 4}])",
                                    R"({"map_size": 256, "filter_width": 0.02, "reference_photons": 400000})");
    const std::string far_sphere = R"({"center": [2.2, 0.3, 2.2], "radius": 0.3, "material": "Ag"})";
    shaded.replace(shaded.find(far_sphere), far_sphere.size(),
                   far_sphere + R"(, {"center": [0.3, 0.6, 0.3], "radius": 0.3, "material": "Ag"})");
    double gpu[2] = {0, 0}, reference[2] = {0, 0};
    int k = 0;
    for (const std::string& json :
         {ring_scene(R"("radius": 1.0, "height": 0.35, "arc_deg": 180)",
                     R"([{"type": "directional", "direction": [0, -0.35, -1], "intensity": 4}])",
                     R"({"map_size": 256, "filter_width": 0.02, "reference_photons": 400000})"),
          shaded}) {
        Scene scene = resolved(json, library);
        resolve_caustic_spectra(scene, library, true);  // the scene asks for no reference image: the map alone
        gpu[k] = gpu_caustic(scene).power;
        const CausticMap* map = reference_caustic_map(scene);
        ASSERT_NE(map, nullptr);
        const PhotonBudget& b = map->budget();
        reference[k] = (b.deposited.r + b.deposited.g + b.deposited.b) / 3;
        ++k;
    }
    EXPECT_LT(gpu[1], 0.9 * gpu[0]) << "the sphere takes part of the caustic";
    EXPECT_NEAR(gpu[1] / gpu[0], reference[1] / reference[0], 0.02)
        << "GPU " << gpu[1] << " / " << gpu[0] << ", reference " << reference[1] << " / " << reference[0];
    EXPECT_NEAR(gpu[0] / reference[0], 1.0, 0.03);
}

}  // namespace test_preview_caustics
}  // namespace metalfit::glpreview
