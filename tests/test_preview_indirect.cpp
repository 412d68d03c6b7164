// The indirect light (indirect effect: the thesis's virtual light sources, ch. 6): the scene key and the plan, the
// power the shot paths carry, the priority scheme's cut-off against sorting, the gather against its own definition,
// the GPU's light maps against the CPU gather, and the virtual lights against the Monte-Carlo reference.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <numbers>
#include <numeric>
#include <random>
#include <string>

#include "effects/indirect/indirect_light_maps.hpp"
#include "effects/indirect/indirect_settings.hpp"
#include "effects/indirect/virtual_lights.hpp"
#include "glpreview/effects/registry.hpp"
#include "glpreview/gl/gl_context.hpp"
#include "glpreview/render/gpu_renderer.hpp"
#include "glpreview/render/room_light_maps.hpp"
#include "glpreview/render/sphere_fresnel.hpp"
#include "libfit/base/errors.hpp"
#include "libfit/color/color_space.hpp"
#include "test_support.hpp"

namespace metalfit::glpreview {
namespace test_preview_indirect {

using test::kData;

// A grey room (every surface 0.5, no panel) with a point light and a box; `indirect` the key's value.
std::string
grey_room(const std::string& indirect = "{}",
          const std::string& lights = R"([{"type": "point", "position": [0.5, 2.2, 0.4], "intensity": 5}])") {
    return R"({"image": {"width": 32, "height": 24},
      "environment": {"type": "room", "panels": [], "wall_x_min": [0.5, 0.5, 0.5], "wall_x_max": [0.5, 0.5, 0.5],
                      "wall_z_min": [0.5, 0.5, 0.5], "wall_z_max": [0.5, 0.5, 0.5], "floor_light": [0.5, 0.5, 0.5],
                      "floor_dark": [0.5, 0.5, 0.5], "ceiling": [0.5, 0.5, 0.5],
                      "boxes": [{"min": [-1.5, 0, -1.5], "max": [-0.5, 1.0, -0.5], "color": [0.5, 0.5, 0.5]}]},
      "lights": )" +
           lights + R"(, "indirect": )" + indirect + R"(,
      "spheres": [{"center": [1.5, 0.4, 1.5], "radius": 0.4, "material": "Ag"}],
      "outputs": {"png": false, "reference": false, "difference": false, "metrics": false}})";
}

std::string parse_error(const std::string& json) {
    try {
        parse_scene(json, "indirect.json");
    } catch (const InputError& e) {
        return e.what();
    }
    return "";
}

TEST(IndirectScene, BadInputNamesTheField) {
    EXPECT_EQ(parse_error(grey_room()), "");
    EXPECT_TRUE(test::Contains(parse_error(grey_room(R"({"paths": 0})")), "indirect.paths: must be in [1, 1024]"));
    EXPECT_TRUE(
        test::Contains(parse_error(grey_room(R"({"evaluation_rate": 1.5})")), "indirect.evaluation_rate: must be in"));
    EXPECT_TRUE(test::Contains(parse_error(grey_room(R"({"bounces": 2})")), "indirect.bounces: unknown key"))
        << parse_error(grey_room(R"({"bounces": 2})"));
}

TEST(IndirectLights, ThePathsCarryTheLightsPower) {
    // A uniformly grey room (positive coordinates and one check per surface, so no surface is shaded; a 1 cm² panel)
    // with a mirror sphere: every path ends on a grey surface or the sphere, and the stored intensity is albedo/π × the
    // power that arrived, so Σ I·π/albedo is the light's power less the sphere's share of its directions.
    const Scene scene = parse_scene(R"({"environment": {"type": "room", "min": [0, 0, 0], "max": [6, 3, 6],
        "checker": 100, "wall_x_min": [0.5, 0.5, 0.5], "wall_x_max": [0.5, 0.5, 0.5], "wall_z_min": [0.5, 0.5, 0.5],
        "wall_z_max": [0.5, 0.5, 0.5], "floor_light": [0.5, 0.5, 0.5], "floor_dark": [0.5, 0.5, 0.5],
        "ceiling": [0.5, 0.5, 0.5], "panels": [{"min": [0.01, 0.01], "max": [0.02, 0.02]}]},
        "lights": [{"type": "point", "position": [3.5, 2.2, 3.4], "intensity": 5}],
        "indirect": {"paths": 1024},
        "spheres": [{"center": [4.5, 0.4, 4.5], "radius": 0.4, "material": "Ag"}]})",
                                    "grey.json");
    const std::vector<VirtualLight> lights = shoot_virtual_lights(scene, *scene.effects.find<IndirectSettings>());
    double stored = 0;
    for (const VirtualLight& v : lights) stored += v.intensity.r * std::numbers::pi / 0.5;
    const double emitted = 5 * 4 * std::numbers::pi;
    const Vec3 to = Vec3{4.5, 0.4, 4.5} - Vec3{3.5, 2.2, 3.4};
    const double blocked = (1 - std::sqrt(1 - 0.16 / dot(to, to))) / 2;  // the sphere's solid angle / 4π
    EXPECT_NEAR(stored / emitted, 1 - blocked, 0.004) << lights.size() << " virtual lights";
    for (const VirtualLight& v : lights) EXPECT_NEAR(length(v.normal), 1.0, 1e-12);
}

TEST(IndirectGather, TheCutOffIsTheSortedRule) {
    std::mt19937 random(7);
    std::uniform_real_distribution<double> uniform(0, 1);
    for (int trial = 0; trial < 50; ++trial) {
        std::vector<double> w(1 + trial * 7);
        for (double& x : w) x = std::pow(uniform(random), 4);
        const double total = std::accumulate(w.begin(), w.end(), 0.0);
        for (const double rate : {0.5, 0.9, 0.99}) {
            const double cut = evaluation_cutoff(w, rate);
            std::vector<double> sorted(w);
            std::sort(sorted.begin(), sorted.end(), std::greater<>());
            double held = 0, expected = 0;
            for (const double x : sorted) {
                held += x;
                expected = x;
                if (held >= rate * total) break;
            }
            EXPECT_NEAR(cut, expected, 1e-6 * sorted.front()) << trial << " " << rate;
        }
    }
}

TEST(IndirectGather, WithNothingInTheWayThePriorityKeepsTheMean) {
    // Without occluders (one tiny sphere in a top corner) every tested sample is visible: the scaled sum's channel mean
    // is the total's, exactly.
    const Scene scene = parse_scene(R"({"environment": {"type": "room", "panels": []},
        "lights": [{"type": "point", "position": [0, 2, 0], "intensity": 3, "colour": [1, 0.6, 0.3]}],
        "indirect": {"paths": 200}, "spheres": [{"center": [2.95, 2.95, 2.95], "radius": 0.01}]})",
                                    "open.json");
    const IndirectSettings& settings = *scene.effects.find<IndirectSettings>();
    const std::vector<VirtualLight> lights = shoot_virtual_lights(scene, settings);
    for (const Vec3 p : {Vec3{0, 0, 0}, Vec3{1.3, 0, -2.1}, Vec3{-2.5, 0, 2.5}}) {
        const IndirectGather all = gather_virtual_lights(scene, lights, settings, {1, 1, 1}, p, {0, 1, 0}, false);
        const IndirectGather some = gather_virtual_lights(scene, lights, settings, {1, 1, 1}, p, {0, 1, 0}, true);
        const auto mean = [](const RGB& c) { return (c.r + c.g + c.b) / 3; };
        EXPECT_NEAR(mean(some.radiance), mean(all.radiance), 1e-12 * mean(all.radiance));
        EXPECT_LT(some.shadow_rays, all.shadow_rays);
        EXPECT_EQ(all.shadow_rays, all.candidates);
    }
}

TEST(IndirectGpu, TheLightMapsAreTheCpuGather) {
    FresnelLibrary library(kData, choose_ocio_config(std::nullopt, kData), "", "indirect.json");
    Scene scene = parse_scene(grey_room(R"({"paths": 128, "light_map_size": 16})"), "indirect.json");
    resolve_effect_materials(scene, library);
    const IndirectSettings& settings = *scene.effects.find<IndirectSettings>();
    const std::vector<VirtualLight> lights = shoot_virtual_lights(scene, settings);
    GlContext context = GlContext::create();
    GpuRenderer renderer(scene, plan_features(scene), {&library.get(scene.spheres[0], "spheres[0]")}, nullptr);
    const RoomLightMaps maps = RoomLightMaps::create({settings.light_map_size});
    render_indirect_light_maps(renderer, lights, maps);
    const std::vector<std::vector<float>> faces = read_room_light_maps(maps);
    const Room& room = scene.environment.room;
    double deviation = 0, norm = 0;
    int texels = 0;
    for (const int face : {2, 0, 5}) {  // the floor, the left wall, the front wall
        const RoomFace f = room_face(room, face);
        for (int y = 0; y < maps.size; ++y)
            for (int x = 0; x < maps.size; ++x) {
                const Vec3 p = f.origin + ((x + 0.5) / maps.size) * f.u + ((y + 0.5) / maps.size) * f.v;
                const RGB cpu = gather_virtual_lights(scene, lights, settings, {1, 1, 1}, p, f.normal, true).radiance;
                const float* gpu =
                    &faces[static_cast<std::size_t>(face)][3 * static_cast<std::size_t>(y * maps.size + x)];
                deviation += std::pow(gpu[0] - cpu.r, 2) + std::pow(gpu[1] - cpu.g, 2) + std::pow(gpu[2] - cpu.b, 2);
                norm += cpu.r * cpu.r + cpu.g * cpu.g + cpu.b * cpu.b;
                ++texels;
            }
    }
    ASSERT_GT(norm, 0);
    EXPECT_LT(std::sqrt(deviation / norm), 0.01) << texels << " texels";
}

TEST(IndirectReference, TheVirtualLightsAgreeWithMonteCarloAwayFromTheWalls) {
    // Away from the walls the clamp and the virtual lights' spacing matter little: the mean over interior floor points
    // of the gather with every shadow ray against the Monte-Carlo reference (the effect's CPU reference).
    Scene scene = parse_scene(grey_room(R"({"paths": 1024, "reference_samples": 1024})"), "indirect.json");
    const IndirectSettings& settings = *scene.effects.find<IndirectSettings>();
    const std::vector<VirtualLight> lights = shoot_virtual_lights(scene, settings);
    const Effect* indirect = nullptr;
    for (const Effect* e : all_effects())
        if (e->name() == "indirect") indirect = e;
    ASSERT_NE(indirect, nullptr);
    double gathered = 0, reference = 0;
    for (const Vec3 p : {Vec3{0.8, 0, -1.2}, Vec3{-1.0, 0, 1.0}, Vec3{1.2, 0, 0.2}, Vec3{0.0, 0, 0.9}}) {
        gathered += gather_virtual_lights(scene, lights, settings, {1, 1, 1}, p, {0, 1, 0}, false).radiance.r;
        reference += indirect->cpu_surface_light(scene, {1, 1, 1}, p, {0, 1, 0}).r;
    }
    EXPECT_NEAR(gathered / reference, 1.0, 0.1) << gathered << " vs " << reference;
}

}  // namespace test_preview_indirect
}  // namespace metalfit::glpreview
