#include "glpreview/render/preview.hpp"

#include <cmath>
#include <memory>

#include "glpreview/effects/bounces.hpp"
#include "glpreview/effects/registry.hpp"
#include "glpreview/render/error_view.hpp"
#include "glpreview/render/exr_metadata.hpp"
#include "glpreview/render/preview_passes.hpp"
#include "glpreview/render/sphere_fresnel.hpp"

namespace metalfit::glpreview {

PreviewResult run_preview(const Scene& given, const PreviewOptions& options, GlContext* context,
                          const std::function<void(const PreviewResult&)>& before_commit) {
    PreviewResult result;
    // The materials are the graph's import: resolved (and fitted) before any pass runs, in sphere order, so that a
    // bad material is reported as before any file is touched; then those of the effects' own objects (rings).
    FresnelLibrary library(options.data_dir, options.ocio, given.space, given.file, given.paths);
    Scene scene = given;
    PreviewRun run{scene, options.output_dir, options.ocio, options.threads, {}, context, {}, {}, {}, {}, {}, {}, {}};
    run.exposure = std::exp2(options.exposure_ev);
    run.exr_colour = ExrColour{chromaticities_of(library.converter()), library.converter().space()};
    for (std::size_t i = 0; i < scene.spheres.size(); ++i)
        run.fresnel.push_back(&library.get(scene.spheres[i], "spheres[" + std::to_string(i) + "]"));
    const bool bounces = max_bounces(scene) > 1;
    if (plan_features(scene).fit_error || scene.outputs.rim || bounces) {
        for (std::size_t i = 0; i < scene.spheres.size(); ++i) {
            Sphere exact = scene.spheres[i];
            exact.fresnel = ReferenceFresnel{};
            run.reference_fresnel.push_back(&library.get(exact, "spheres[" + std::to_string(i) + "]"));
        }
    }
    if (bounces) {  // the spectral reference of the bounce orders (render/bounce_orders.hpp)
        for (std::size_t i = 0; i < scene.spheres.size(); ++i)
            run.spectral.push_back(std::make_shared<const SpectralFresnel>(
                library.material(scene.spheres[i], "spheres[" + std::to_string(i) + "]"), library.colorimetry()));
        run.uplift = std::make_shared<const RgbUplift>(library.colorimetry(), library.converter());
    }
    run.luminance = luminance_weights(library.converter());
    run.delta_e = delta_e_basis(library.converter());
    run.exr_metadata = sphere_metadata(scene, run.fresnel);
    resolve_effect_materials(scene, library);

    graph::PassGraph graph;
    const Features features = plan_features(scene);
    const PreviewHandles h = add_preview_passes(graph, scene, features, &run);
    graph.retain(h.beauty);
    graph.retain(h.reference);
    graph.retain(h.difference);
    if (h.fit_reference) graph.retain(*h.fit_reference);
    graph.retain(h.localization);
    graph.retain(h.frame_times);
    graph.retain(h.metrics);
    if (h.reference_standard_error) graph.retain(*h.reference_standard_error);
    graph.before_first_gpu_pass([&run] { run.open_gl(); });
    graph.compile();
    skip_unneeded_effects(graph);
    result.plan = plan_of(graph, features);
    graph.execute();

    result.renderer = run.renderer_name;
    if (const Image* beauty = graph.result(h.beauty)) result.beauty = *beauty;
    if (const ReferenceRender* reference = graph.result(h.reference)) result.reference = *reference;
    if (h.reference_standard_error)
        if (const Image* error = graph.result(*h.reference_standard_error)) result.reference_standard_error = *error;
    if (const Image* difference = graph.result(h.difference)) result.difference = *difference;
    if (h.fit_reference)
        if (const Image* fit_reference = graph.result(*h.fit_reference)) result.fit_reference = *fit_reference;
    if (const Image* localization = graph.result(h.localization)) result.localization = *localization;
    if (const FrameTimes* frame_ms = graph.result(h.frame_times)) result.frame_ms = *frame_ms;
    if (const Json* metrics = graph.result(h.metrics)) result.metrics = *metrics;
    result.written = run.written;
    if (before_commit) before_commit(result);
    run.commit_outputs();
    return result;
}

}  // namespace metalfit::glpreview
