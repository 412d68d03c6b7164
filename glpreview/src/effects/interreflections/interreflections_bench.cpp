#include "glpreview/effects/interreflections_bench.hpp"

#include <functional>
#include <memory>

#include "bounce_maps.hpp"
#include "glpreview/effects/bounces.hpp"
#include "glpreview/render/bounce_orders.hpp"
#include "glpreview/render/bounces_bench.hpp"
#include "glpreview/render/cpu_reference.hpp"
#include "glpreview/render/delta_e_view.hpp"
#include "glpreview/render/environment.hpp"
#include "glpreview/render/gpu_renderer.hpp"
#include "libfit/base/sample_statistics.hpp"
#include "render/frame_timing.hpp"

namespace metalfit::glpreview {

Scene interreflections_bench_scene(bool quick, int bounces) {
    Scene scene = bounces_bench_scene(quick);  // the compounding table's scene: the cost and the error of one picture
    if (quick) scene.environment.cube_size = 64;
    for (Sphere& sphere : scene.spheres) sphere.reflection = ReflectionMode::distance_impostor;
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
    // Each frame against the CPU reference of its bounce count: over every sphere pixel, and over the pixels whose
    // path reaches the last bounce.
    const EnvironmentTracer tracer(scenes[0].environment);
    const DeltaEBasis basis = delta_e_basis(library.converter());
    std::vector<MaskedError> all, reaching;
    for (const Scene& scene : scenes) {
        auto gpu = std::make_unique<GpuRenderer>(scene, plan_features(scene), fresnel, nullptr, &context.programs());
        gpu->capture_environment();         // and, beyond one bounce, the spheres' maps (derived from the room's cube)
        const Image frame = gpu->render();  // compiles its programs before the timing
        const int bounces = max_bounces(scene);
        const ReferenceRender reference = render_reference(scene, fresnel, tracer, 0, nullptr, bounces);
        all.push_back(masked_errors(frame, reference.image, sphere_pixels_mask(reference), 1, basis).front());
        reaching.push_back(
            masked_errors(frame, reference.image, reaching_mask(scene, reference, bounces), 1, basis).front());
        GpuRenderer* raw = gpu.get();
        variants.push_back([raw] { raw->draw_frame_for_timing(); });
        renderers.push_back(std::move(gpu));
    }
    // Every sphere's map made once (what a scene change costs), per sphere below.
    GpuRenderer& two = *renderers[1];
    const BouncePlan plan = plan_bounces(scenes[1]);
    BounceMaps remade;
    variants.push_back([&two, &plan, &remade] { render_bounce_maps(two, plan, remade); });
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
                             {"ratio_noise", r.noise},
                             {"vs_reference", masked_error_json(all[i])},
                             {"vs_reference_reaching", masked_error_json(reaching[i])},
                             {"reaching_pixels", reaching[i].pixels}});
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
