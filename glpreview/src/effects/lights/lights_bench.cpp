#include "glpreview/effects/lights_bench.hpp"

#include <functional>
#include <memory>

#include "glpreview/render/gpu_bench.hpp"
#include "glpreview/render/gpu_renderer.hpp"
#include "libfit/base/sample_statistics.hpp"
#include "light.hpp"
#include "render/frame_timing.hpp"
#include "shadow_maps.hpp"

namespace metalfit::glpreview {

namespace {

// The bench room with `lights` point lights (in a row under the ceiling) and the sphere at `roughness`.
Scene lit_scene(const PreviewOptions& options, bool quick, int lights, double roughness) {
    GlossyVariant variant{roughness, GlossyMethod::prefiltered,
                          roughness > 0 ? ReflectionMode::box_parallax : ReflectionMode::classic, 8};
    Scene scene = glossy_bench_scene(options.data_dir, quick, variant);
    Lights all;
    for (int i = 0; i < lights; ++i) {
        Light light;
        light.position = {-1.5 + i * 1.0, 2.5, 1.5};
        light.intensity = 4;
        all.lights.push_back(light);
    }
    if (lights > 0) scene.effects.set(all);
    return scene;
}

}  // namespace

nlohmann::ordered_json bench_lights(GlContext& context, const PreviewOptions& options, bool quick) {
    const int rounds = quick ? 5 : 15;
    struct Case {
        std::string name;
        Scene scene;
    };
    std::vector<Case> cases{{"mirror frame (roughness 0, classic, no light)", lit_scene(options, quick, 0, 0)},
                            {"rough frame (0.3, prefiltered), no light", lit_scene(options, quick, 0, 0.3)},
                            {"rough frame, 1 point light", lit_scene(options, quick, 1, 0.3)},
                            {"rough frame, 4 point lights", lit_scene(options, quick, 4, 0.3)}};
    FresnelLibrary library(options.data_dir, options.ocio, cases[0].scene.space, cases[0].scene.file);
    const SphereFresnel* gold = &library.get(cases[0].scene.spheres.at(0), "spheres[0]");
    std::vector<std::unique_ptr<GpuRenderer>> renderers;
    std::vector<std::function<void()>> variants;
    for (const Case& c : cases) {
        auto gpu = std::make_unique<GpuRenderer>(c.scene, plan_features(c.scene),
                                                 std::vector<const SphereFresnel*>{gold}, nullptr, &context.programs());
        gpu->capture_environment();
        gpu->render();  // compiles its programs and makes its shadow maps before the timing
        GpuRenderer* raw = gpu.get();
        variants.push_back([raw] { raw->draw_frame_for_timing(); });
        renderers.push_back(std::move(gpu));
    }
    // The shadow pass of one light: its six faces into a map of the renderer's.
    const Lights& one = *cases[2].scene.effects.find<Lights>();
    const ShadowLayout layout = shadow_layout(cases[2].scene, one);
    const ShadowMaps maps = ShadowMaps::create({kShadowMapSize, layout.cubes, layout.planes});
    GpuRenderer& lit = *renderers[2];
    variants.push_back([&lit, &one, &layout, &maps] { render_shadow_maps(lit, one, layout, maps); });
    const RoundTimes ms = interleaved_rounds(variants, rounds);
    check_gl("the lights benchmark");

    nlohmann::ordered_json j;
    j["renderer"] = context.renderer();
    j["size"] = {cases[0].scene.width, cases[0].scene.height};
    j["rounds"] = rounds;
    j["rows"] = nlohmann::ordered_json::array();
    std::vector<std::string> names;
    for (const Case& c : cases) names.push_back(c.name);
    names.push_back("shadow pass of 1 light (256² cube, 6 faces)");
    for (std::size_t i = 0; i < names.size(); ++i) {
        const Ratio r = paired_ratio(ms[i], ms[0]);
        j["rows"].push_back({{"variant", names[i]},
                             {"ms", median(ms[i])},
                             {"ratio_to_mirror_frame", r.median},
                             {"ratio_noise", r.noise}});
    }
    // Per light: the frame with four lights less the frame without, over four; the shadow pass as it is.
    std::vector<double> per_light;
    for (std::size_t r = 0; r < ms[3].size() && r < ms[1].size() && r < ms[0].size(); ++r)
        per_light.push_back((ms[3][r] - ms[1][r]) / 4 / ms[0][r]);
    j["light_pass_per_light"] = {{"ratio_to_mirror_frame", median(per_light)},
                                 {"ratio_noise", (quantile(per_light, 0.75) - quantile(per_light, 0.25)) / 2}};
    const Ratio shadow = paired_ratio(ms[4], ms[0]);
    j["shadow_pass_per_light"] = {{"ratio_to_mirror_frame", shadow.median}, {"ratio_noise", shadow.noise}};
    return j;
}

}  // namespace metalfit::glpreview
