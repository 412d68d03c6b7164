#include "glpreview/effects/caustic_maps_bench.hpp"

#include <functional>
#include <memory>
#include <optional>

#include "caustic_maps.hpp"
#include "glpreview/effects/registry.hpp"
#include "glpreview/render/gpu_bench.hpp"
#include "glpreview/render/gpu_renderer.hpp"
#include "libfit/base/sample_statistics.hpp"
#include "render/frame_timing.hpp"

namespace metalfit::glpreview {

nlohmann::ordered_json bench_caustic_maps(GlContext& context, const PreviewOptions& options, bool quick) {
    const int rounds = quick ? 5 : 15;
    Scene scene = load_scene(options.data_dir / "scenes" / "ring-caustic.json");
    if (quick) {
        scene.width = 160;
        scene.height = 120;
        scene.environment.cube_size = 128;
    }
    FresnelLibrary library(options.data_dir, options.ocio, scene.space, scene.file);
    std::vector<const SphereFresnel*> fresnel;
    for (std::size_t i = 0; i < scene.spheres.size(); ++i)
        fresnel.push_back(&library.get(scene.spheres[i], "spheres[" + std::to_string(i) + "]"));
    resolve_effect_materials(scene, library);
    GpuRenderer gpu(scene, plan_features(scene), fresnel, nullptr, &context.programs());
    gpu.capture_environment();  // with the scene's own light maps (and the room's distance cube the maps reuse)
    gpu.render();               // compiles its programs before the timing
    const CausticPlan plan = plan_caustics(scene);
    struct Case {
        int photons_edge, light_map_size;
    };
    const std::vector<Case> cases{{32, 256}, {64, 256}, {128, 256}, {256, 256}, {256, 512}};
    std::vector<std::function<void()>> variants{[&gpu] { gpu.draw_frame_for_timing(); }};
    std::vector<RoomLightMaps> maps;
    maps.reserve(cases.size());
    for (const Case& c : cases) {
        CausticSettings settings = caustic_settings(scene);
        settings.map_size = c.photons_edge;
        settings.light_map_size = c.light_map_size;
        maps.push_back(RoomLightMaps::create({c.light_map_size}));
        const RoomLightMaps* target = &maps.back();
        render_caustic_light_maps(gpu, plan, settings, *target);  // its programs compiled before the timing
        variants.push_back(
            [&gpu, &plan, settings, target] { render_caustic_light_maps(gpu, plan, settings, *target); });
    }
    const RoundTimes ms = interleaved_rounds(variants, rounds);
    check_gl("the caustic maps benchmark");

    nlohmann::ordered_json j;
    j["renderer"] = context.renderer();
    j["size"] = {scene.width, scene.height};
    j["rounds"] = rounds;
    j["rows"] = nlohmann::ordered_json::array();
    j["rows"].push_back({{"variant", "mirror frame (the ring scene)"},
                         {"photons", 0},
                         {"light_map_size", 0},
                         {"ms", median(ms[0])},
                         {"ratio_to_mirror_frame", 1.0},
                         {"ratio_noise", 0.0}});
    for (std::size_t i = 0; i < cases.size(); ++i) {
        const Ratio r = paired_ratio(ms[i + 1], ms[0]);
        const int edge = cases[i].photons_edge;
        j["rows"].push_back({{"variant", "caustic map " + std::to_string(edge) + "² + splat into six " +
                                             std::to_string(cases[i].light_map_size) + "² light maps"},
                             {"photons", edge * edge},
                             {"light_map_size", cases[i].light_map_size},
                             {"ms", median(ms[i + 1])},
                             {"ratio_to_mirror_frame", r.median},
                             {"ratio_noise", r.noise}});
    }
    return j;
}

}  // namespace metalfit::glpreview
