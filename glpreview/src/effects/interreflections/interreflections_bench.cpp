#include "glpreview/effects/interreflections_bench.hpp"

#include <functional>
#include <memory>

#include "bounce_maps.hpp"
#include "bounces.hpp"
#include "glpreview/render/gpu_renderer.hpp"
#include "libfit/base/sample_statistics.hpp"
#include "render/frame_timing.hpp"

namespace metalfit::glpreview {

Scene interreflections_bench_scene(bool quick, int bounces) {
    Scene scene;
    scene.file = "interreflections-bench.json";
    scene.width = scene.height = quick ? 96 : 256;
    scene.camera.position = {0, 1.7, 2.4};
    scene.camera.look_at = {0, 0.5, 0};
    scene.environment.cube_size = quick ? 64 : 256;
    const char* metals[] = {"Au", "Cu", "Ag", "Al"};
    const Vec3 centres[] = {{-0.45, 0.4, -0.45}, {0.45, 0.4, -0.45}, {-0.45, 0.4, 0.45}, {0.45, 0.4, 0.45}};
    for (int i = 0; i < 4; ++i) {
        Sphere sphere;
        sphere.center = centres[i];
        sphere.radius = 0.4;
        sphere.material = metals[i];
        scene.spheres.push_back(sphere);
    }
    if (bounces > 1) scene.effects.set(Interreflections{bounces});
    return scene;
}

nlohmann::ordered_json bench_interreflections(GlContext& context, const PreviewOptions& options, bool quick) {
    const int rounds = quick ? 5 : 15;
    std::vector<Scene> scenes;
    for (int bounces = 1; bounces <= 4; ++bounces) scenes.push_back(interreflections_bench_scene(quick, bounces));
    FresnelLibrary library(options.data_dir, options.ocio, scenes[0].space, scenes[0].file);
    std::vector<const SphereFresnel*> fresnel;
    for (std::size_t i = 0; i < scenes[0].spheres.size(); ++i)
        fresnel.push_back(&library.get(scenes[0].spheres[i], "spheres[" + std::to_string(i) + "]"));
    std::vector<std::unique_ptr<GpuRenderer>> renderers;
    std::vector<std::function<void()>> variants;
    for (const Scene& scene : scenes) {
        auto gpu = std::make_unique<GpuRenderer>(scene, plan_features(scene), fresnel, nullptr, &context.programs());
        gpu->capture_environment();  // and, beyond one bounce, the spheres' maps (derived from the room's cube)
        gpu->render();               // compiles its programs before the timing
        GpuRenderer* raw = gpu.get();
        variants.push_back([raw] { raw->draw_frame_for_timing(); });
        renderers.push_back(std::move(gpu));
    }
    // Every sphere's map made once (what a scene change costs), per sphere below.
    GpuRenderer& two = *renderers[1];
    const BouncePlan plan = plan_bounces(scenes[1]);
    variants.push_back([&two, &plan] { render_bounce_maps(two, plan); });
    const RoundTimes ms = interleaved_rounds(variants, rounds);
    check_gl("the inter-reflections benchmark");

    nlohmann::ordered_json j;
    j["renderer"] = context.renderer();
    j["size"] = {scenes[0].width, scenes[0].height};
    j["map_size"] = scenes[0].environment.cube_size;
    j["rounds"] = rounds;
    j["rows"] = nlohmann::ordered_json::array();
    for (std::size_t i = 0; i < scenes.size(); ++i) {
        const Ratio r = paired_ratio(ms[i], ms[0]);
        j["rows"].push_back({{"variant", "frame at max_bounces " + std::to_string(i + 1) +
                                             (i == 0 ? " (the room's cube only)" : " (maps made beforehand)")},
                             {"ms", median(ms[i])},
                             {"ratio_to_one_bounce_frame", r.median},
                             {"ratio_noise", r.noise}});
    }
    std::vector<double> per_sphere;
    const double mapped = static_cast<double>(plan.mapped.size());
    for (std::size_t r = 0; r < ms[4].size() && r < ms[0].size(); ++r)
        per_sphere.push_back(ms[4][r] / mapped / ms[0][r]);
    j["map_update_per_sphere"] = {{"ms", median(ms[4]) / mapped},
                                  {"ratio_to_one_bounce_frame", median(per_sphere)},
                                  {"ratio_noise", (quantile(per_sphere, 0.75) - quantile(per_sphere, 0.25)) / 2}};
    return j;
}

}  // namespace metalfit::glpreview
