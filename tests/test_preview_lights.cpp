// The lights effect: its scene keys and their bad input, its plan, the CPU reference's light against closed forms,
// and the GPU (distance maps + PCSS, GGX highlights, emitters) against that reference: the room's light, a shadow's
// umbra, a highlight's position and size, a sphere light seen in a mirror.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <numbers>
#include <string>

#include "effects/lights/cpu_lights.hpp"
#include "effects/lights/light.hpp"
#include "glpreview/render/plan.hpp"
#include "glpreview/render/preview.hpp"
#include "glpreview/scene/camera.hpp"
#include "libfit/base/errors.hpp"
#include "libfit/color/color_space.hpp"
#include "test_support.hpp"

namespace metalfit::glpreview {
namespace test_preview_lights {

using test::kData;

// A 6 × 3 × 6 room of grey surfaces without ceiling panels, the camera looking down at the floor.
std::string room_scene(const std::string& lights, const std::string& spheres, int width = 96, int height = 72) {
    return R"({"image": {"width": )" + std::to_string(width) + R"(, "height": )" + std::to_string(height) + R"(},
      "camera": {"position": [0, 2.2, 2.6], "look_at": [0, 0.3, 0], "fov_y_deg": 60},
      "environment": {"type": "room", "panels": [], "wall_x_min": [0.2, 0.2, 0.2], "wall_x_max": [0.2, 0.2, 0.2],
                      "wall_z_min": [0.2, 0.2, 0.2], "wall_z_max": [0.2, 0.2, 0.2], "ceiling": [0.1, 0.1, 0.1],
                      "floor_light": [0.3, 0.3, 0.3], "floor_dark": [0.3, 0.3, 0.3]},
      "lights": [)" +
           lights + R"(],
      "spheres": [)" +
           spheres + R"(],
      "outputs": {"reference_samples": 64, "png": false}})";
}

std::string parse_error(const std::string& json) {
    try {
        parse_scene(json, "lights.json");
    } catch (const InputError& e) {
        return e.what();
    }
    return "";
}

const std::string kFarSphere = R"({"center": [2.4, 0.2, -2.4], "radius": 0.2, "reflection": "classic"})";

TEST(LightsScene, ReadsEveryTypeWithItsUnits) {
    const Scene scene =
        parse_scene(room_scene(R"({"type": "point", "position": [0, 2, 0], "intensity": 2, "unit": "W/sr"},
        {"type": "spot", "position": [1, 2.5, 1], "direction": [0, -2, 0], "cone_inner_deg": 20, "cone_outer_deg": 30, "intensity": 5},
        {"type": "directional", "direction": [1, -1, 0], "colour": [1, 0.9, 0.8], "intensity": 0.5, "unit": "W/m2"},
        {"type": "sphere", "position": [-1, 2, 1], "radius": 0.2, "intensity": 10, "unit": "W/m2/sr"})",
                               kFarSphere),
                    "lights.json");
    const Lights* lights = scene.effects.find<Lights>();
    ASSERT_NE(lights, nullptr);
    ASSERT_EQ(lights->lights.size(), 4u);
    EXPECT_EQ(lights->lights[1].type, LightType::spot);
    EXPECT_NEAR(lights->lights[1].direction.y, -1.0, 1e-15);  // normalised
    EXPECT_NEAR(length(lights->lights[2].direction), 1.0, 1e-15);
    EXPECT_DOUBLE_EQ(lights->lights[2].power().b, 0.4);
    EXPECT_DOUBLE_EQ(lights->lights[3].radius, 0.2);
}

TEST(LightsScene, BadInputNamesTheField) {
    const auto error = [](const std::string& light, const std::string& spheres = kFarSphere) {
        return parse_error(room_scene(light, spheres));
    };
    EXPECT_TRUE(test::Contains(error(R"({"type": "laser", "position": [0, 2, 0], "intensity": 1})"),
                               "lights[0].type: unknown value 'laser'"));
    EXPECT_TRUE(test::Contains(error(R"({"type": "point", "position": [0, 2, 0], "intensity": -1})"),
                               "lights[0].intensity: must be in [0"));
    EXPECT_TRUE(test::Contains(error(R"({"type": "point", "position": [0, 2, 0]})"), "lights[0].intensity: missing"));
    EXPECT_TRUE(test::Contains(error(R"({"type": "point", "position": [0, 9, 0], "intensity": 1})"),
                               "lights[0].position: outside the room"));
    EXPECT_TRUE(test::Contains(error(R"({"type": "sphere", "position": [0, 2.9, 0], "radius": 0.2, "intensity": 1})"),
                               "lights[0].position: the light's sphere must lie inside the room"));
    EXPECT_TRUE(test::Contains(error(R"({"type": "point", "position": [2.4, 0.25, -2.4], "intensity": 1})"),
                               "lights[0].position: inside sphere 0"));
    EXPECT_TRUE(test::Contains(
        error(
            R"({"type": "spot", "position": [0, 2, 0], "direction": [0, -1, 0], "cone_outer_deg": 0, "intensity": 1})"),
        "lights[0].cone_outer_deg: must be in (0, 90]"));
    EXPECT_TRUE(test::Contains(
        error(
            R"({"type": "spot", "position": [0, 2, 0], "direction": [0, -1, 0], "cone_outer_deg": 95, "intensity": 1})"),
        "lights[0].cone_outer_deg: must be in [0, 90]"));
    EXPECT_TRUE(
        test::Contains(error(R"({"type": "spot", "position": [0, 2, 0], "direction": [0, 0, 0], "intensity": 1})"),
                       "lights[0].direction: must be a non-zero vector"));
    EXPECT_TRUE(test::Contains(
        error(R"({"type": "directional", "position": [0, 2, 0], "direction": [0, -1, 0], "intensity": 1})"),
        "lights[0].position: means nothing for a directional light"));
    EXPECT_TRUE(test::Contains(error(R"({"type": "point", "position": [0, 2, 0], "intensity": 1, "unit": "lm"})"),
                               "lights[0].unit: 'lm': a point light's intensity is in W/sr"));
    const std::string sky = R"({"image": {"width": 8, "height": 8}, "environment": {"type": "sphere-room"},
        "lights": [{"type": "point", "position": [0, 1, 0], "intensity": 1}], "spheres": [{"center": [0, 1, -2]}]})";
    EXPECT_TRUE(test::Contains(parse_error(sky), "lights: lights need a room environment"));
}

TEST(LightsPlan, ShadowMapsOnlyForLightsThatCanCastAndNoneWithoutLights) {
    const Scene lit = parse_scene(room_scene(R"({"type": "point", "position": [0, 2, 0], "intensity": 2},
        {"type": "spot", "position": [-2, 2, 2], "direction": [-1, 0, 1], "cone_inner_deg": 5, "cone_outer_deg": 10, "intensity": 5})",
                                             kFarSphere),
                                  "lights.json");
    const Plan plan = build_plan(lit);
    ASSERT_TRUE(plan.runs("shadow-maps"));
    const std::string text = explain(plan, lit);
    EXPECT_TRUE(test::Contains(text, "light 0 (point): a 256² distance cube map around it")) << text;
    EXPECT_TRUE(test::Contains(text, "light 1 (spot): no sphere or room box lies in its cone")) << text;
    EXPECT_LT(text.find("shadow-maps"), text.find("capture-environment"));  // the capture reads the maps

    const Scene dark = parse_scene(
        room_scene(
            R"({"type": "spot", "position": [-2, 2, 2], "direction": [-1, 0, 1], "cone_inner_deg": 5, "cone_outer_deg": 10, "intensity": 5})",
            kFarSphere),
        "lights.json");
    EXPECT_FALSE(build_plan(dark).runs("shadow-maps"));
    EXPECT_TRUE(test::Contains(explain(build_plan(dark), dark),
                               "shadow-maps: light 0 (spot): no sphere or room box lies in its cone"));
}

TEST(CpuLights, AnUnoccludedSphereLightLightsLikeThePointOfItsPower) {
    // Above the horizon, a uniform sphere's irradiance is that of a point source of its power at its centre:
    // E = L π r² / d² cos θ (the spiral quadrature against the closed form).
    const Scene scene = parse_scene(
        room_scene(R"({"type": "sphere", "position": [0.3, 2.0, -0.2], "radius": 0.3, "intensity": 7})", kFarSphere),
        "lights.json");
    const Lights& lights = *scene.effects.find<Lights>();
    const RGB albedo{0.5, 0.25, 1.0};
    for (const Vec3 p : {Vec3{0, 0, 0}, Vec3{-1.5, 0, 1.0}, Vec3{1.2, 0, -1.6}}) {
        const Vec3 to = lights.lights[0].position - p;
        const double d = length(to), cos_t = to.y / d;
        const double expected = 7 * std::numbers::pi * 0.09 / (d * d) * cos_t / std::numbers::pi;
        const RGB got = light_on_surface(scene, lights, albedo, p, {0, 1, 0});
        EXPECT_NEAR(got.r, 0.5 * expected, 2e-3 * expected);
        EXPECT_NEAR(got.b, 1.0 * expected, 2e-3 * expected);
    }
    // Behind an occluder (a sphere between the point and the light): none.
    const Scene blocked =
        parse_scene(room_scene(R"({"type": "sphere", "position": [0, 2.0, 0], "radius": 0.1, "intensity": 7})",
                               R"({"center": [0, 1, 0], "radius": 0.4})"),
                    "lights.json");
    EXPECT_EQ(light_on_surface(blocked, *blocked.effects.find<Lights>(), albedo, {0, 0, 0}, {0, 1, 0}).r, 0.0);
}

TEST(CpuLights, ASpotsConeWeightIsTheShadersSmoothstep) {
    Light spot;
    spot.type = LightType::spot;
    spot.cone_inner_deg = 20;
    spot.cone_outer_deg = 30;
    EXPECT_DOUBLE_EQ(spot_weight(spot, 1.0), 1.0);
    EXPECT_DOUBLE_EQ(spot_weight(spot, std::cos(31 * std::numbers::pi / 180)), 0.0);
    const double middle = std::cos(25 * std::numbers::pi / 180);
    const double t = (middle - std::cos(30 * std::numbers::pi / 180)) /
                     (std::cos(20 * std::numbers::pi / 180) - std::cos(30 * std::numbers::pi / 180));
    EXPECT_NEAR(spot_weight(spot, middle), t * t * (3 - 2 * t), 1e-15);
}

PreviewOptions options() { return {kData, choose_ocio_config(std::nullopt, kData), {}, 1}; }

// Pixels seeing the room (not a sphere) in the reference, where GPU and CPU agree within `tolerance` (relative).
double share_agreeing(const PreviewResult& r, double tolerance) {
    int agree = 0, total = 0;
    for (int y = 0; y < r.beauty->height; ++y)
        for (int x = 0; x < r.beauty->width; ++x) {
            if (r.reference->sphere_id[static_cast<std::size_t>(y) * r.beauty->width + x] >= 0) continue;
            const double a = r.beauty->at(x, y).g, b = r.reference->image.at(x, y).g;
            ++total;
            agree += std::abs(a - b) <= tolerance * std::max(b, 1e-3) ? 1 : 0;
        }
    return double(agree) / total;
}

TEST(LightsGpu, TheLitRoomAgreesWithTheReferenceAwayFromShadowEdges) {
    const Scene scene = parse_scene(room_scene(R"({"type": "point", "position": [0.5, 2.2, 0.3], "intensity": 3},
        {"type": "directional", "direction": [0.3, -1, -0.2], "intensity": 0.4})",
                                               R"({"center": [0, 0.6, 0], "radius": 0.4, "reflection": "classic"})"),
                                    "lights.json");
    const PreviewResult lit = run_preview(scene, options());
    EXPECT_GT(share_agreeing(lit, 0.02), 0.95);
    // The light is there: the same room without it is darker where the point light shines.
    Scene dark = scene;
    dark.effects = {};
    const PreviewResult unlit = run_preview(dark, options());
    const auto& id = lit.reference->sphere_id;
    double brighter = 0;
    int count = 0;
    for (std::size_t i = 0; i < id.size(); ++i)
        if (id[i] < 0) {
            const int x = static_cast<int>(i % static_cast<std::size_t>(scene.width)),
                      y = static_cast<int>(i / static_cast<std::size_t>(scene.width));
            brighter += lit.beauty->at(x, y).g - unlit.beauty->at(x, y).g;
            ++count;
        }
    EXPECT_GT(brighter / count, 0.02);
}

TEST(LightsGpu, AShadowsUmbraIsDarkOnBothAndTheLitFloorLit) {
    // A point light right above a sphere: the floor point below the sphere is in its umbra; one far off is lit.
    const Scene scene =
        parse_scene(room_scene(R"({"type": "point", "position": [0, 2.6, 0], "intensity": 12})",
                               R"({"center": [0, 1.2, 0], "radius": 0.5, "reflection": "classic"})", 160, 120),
                    "lights.json");
    const PreviewResult r = run_preview(scene, options());
    const CameraBasis basis = camera_basis(scene.camera, scene.width, scene.height);
    // The pixel whose ray meets the floor at (x, 0, z).
    const auto pixel_of = [&](Vec3 floor_point) {
        const Vec3 d = normalize(floor_point - basis.position);
        const double fx = dot(d, basis.right) / dot(basis.right, basis.right) / dot(d, basis.forward);
        const double fy = dot(d, basis.up) / dot(basis.up, basis.up) / dot(d, basis.forward);
        const int px = static_cast<int>((fx + 1) / 2 * scene.width), py = static_cast<int>((fy + 1) / 2 * scene.height);
        return std::pair<int, int>{px, scene.height - 1 - py};
    };
    const auto [ux, uy] = pixel_of({0.0, 0, 0.75});  // under the sphere's shadow, seen past the sphere
    const auto [lx, ly] = pixel_of({1.8, 0, 1.2});   // far from it
    ASSERT_LT(r.reference->sphere_id[static_cast<std::size_t>(uy) * scene.width + ux], 0)
        << "the umbra pixel sees the floor";
    const double emission = 0.3;
    EXPECT_NEAR(r.reference->image.at(ux, uy).g, emission, 1e-6);  // exact: no light reaches it (a float image)
    EXPECT_NEAR(r.beauty->at(ux, uy).g, emission, 0.01);
    EXPECT_GT(r.reference->image.at(lx, ly).g, emission + 0.05);
    EXPECT_NEAR(r.beauty->at(lx, ly).g, r.reference->image.at(lx, ly).g, 0.02 * r.reference->image.at(lx, ly).g);
}

TEST(LightsGpu, ARoughSpheresHighlightSitsWhereTheReferencesDoes) {
    const Scene scene = parse_scene(room_scene(R"({"type": "point", "position": [1.2, 2.4, 1.6], "intensity": 6})",
                                               R"({"center": [0, 0.6, 0], "radius": 0.6, "roughness": 0.25})", 128, 96),
                                    "lights.json");
    const PreviewResult r = run_preview(scene, options());
    const auto brightest = [&](const Image& image) {
        std::pair<int, int> at{0, 0};
        double best = -1;
        for (int y = 0; y < image.height; ++y)
            for (int x = 0; x < image.width; ++x)
                if (r.reference->sphere_id[static_cast<std::size_t>(y) * image.width + x] == 0 &&
                    image.at(x, y).g > best) {
                    best = image.at(x, y).g;
                    at = {x, y};
                }
        return std::pair{at, best};
    };
    const auto [gpu_at, gpu_peak] = brightest(*r.beauty);
    const auto [cpu_at, cpu_peak] = brightest(r.reference->image);
    EXPECT_LE(std::abs(gpu_at.first - cpu_at.first) + std::abs(gpu_at.second - cpu_at.second), 4);
    EXPECT_NEAR(gpu_peak, cpu_peak, 0.15 * cpu_peak);
    EXPECT_GT(cpu_peak, 1.0);  // a highlight, well above the room's light
}

TEST(LightsGpu, AMirrorSeesASphereLightAsItsFresnelTimesItsRadiance) {
    // The camera looks at a mirror sphere whose reflection of the sphere light is in view.
    const Scene scene =
        parse_scene(room_scene(R"({"type": "sphere", "position": [0, 2.4, 1.4], "radius": 0.3, "intensity": 20})",
                               R"({"center": [0, 0.6, 0], "radius": 0.6, "reflection": "classic"})", 128, 96),
                    "lights.json");
    const PreviewResult r = run_preview(scene, options());
    int emitter_pixels = 0, agreeing = 0;
    for (int y = 0; y < scene.height; ++y)
        for (int x = 0; x < scene.width; ++x) {
            if (r.reference->sphere_id[static_cast<std::size_t>(y) * scene.width + x] != 0) continue;
            if (r.reference->image.at(x, y).g < 5) continue;  // F · 20 where the mirror shows the light
            ++emitter_pixels;
            agreeing +=
                std::abs(r.beauty->at(x, y).g - r.reference->image.at(x, y).g) < 0.01 * r.reference->image.at(x, y).g;
        }
    EXPECT_GT(emitter_pixels, 3);
    EXPECT_GT(agreeing, emitter_pixels * 8 / 10);
}

}  // namespace test_preview_lights
}  // namespace metalfit::glpreview
