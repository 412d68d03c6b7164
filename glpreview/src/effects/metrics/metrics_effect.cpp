#include "metrics_effect.hpp"

#include "glpreview/render/delta_e_view.hpp"
#include "glpreview/render/frame_inputs.hpp"
#include "glpreview/render/preview_passes.hpp"
#include "glpreview/render/sphere_metrics.hpp"
#include "libfit/base/text.hpp"

namespace metalfit::glpreview {
namespace {

using graph::Builder;
using graph::Handle;
using graph::Out;
using graph::Processor;
using graph::Resources;

Json metrics_json(const PreviewRun& run, const Image& beauty, const ReferenceRender& reference,
                  const Image& localization, const Image* standard_error, const Image* fit_reference,
                  const Json* bounce_orders, const std::vector<std::pair<std::string, const Json*>>& effect_metrics) {
    const Scene& scene = run.scene;
    Json j;
    j["schema"] = "metalfit.preview-metrics/1";
    j["scene"] = scene.file.filename().string();
    j["renderer"] = run.renderer_name;
    j["size"] = {scene.width, scene.height};
    j["space"] = scene.space.empty() ? std::string("scene_linear") : scene.space;  // as the scene names it
    const auto errors = sphere_errors(beauty, reference, scene.spheres.size());
    // The models' error alone: against the frame with the exact curves, over the same sphere masks.
    const auto fit_errors = fit_reference ? sphere_errors(beauty, ReferenceRender{*fit_reference, reference.sphere_id},
                                                          scene.spheres.size())
                                          : std::vector<SphereError>{};
    // ΔE2000 of the beauty frame against the reference, per pixel, over the same masks (white Y_w = 1).
    const auto delta_e =
        sphere_delta_e(delta_e_2000(beauty, reference.image, run.delta_e), reference, scene.spheres.size());
    const auto effort = sphere_localization(localization, reference, scene.spheres.size());
    const auto noise = standard_error ? sphere_reference_noise(*standard_error, reference, scene.spheres.size())
                                      : std::vector<double>(scene.spheres.size(), 0.0);
    j["spheres"] = Json::array();
    for (std::size_t i = 0; i < scene.spheres.size(); ++i) {
        const Sphere& s = scene.spheres[i];
        // A localized rough sphere looks nothing up along its reflection mode: no impostor statistics.
        const bool impostor =
            s.reflection == ReflectionMode::distance_impostor && !(s.rough() && s.glossy == GlossyMethod::localized);
        Json e;
        e["sphere"] = i;
        e["material"] = run.fresnel[i]->material;
        e["source"] = run.fresnel[i]->source;
        e["stack"] = run.fresnel[i]->stack.empty() ? Json(nullptr) : Json(run.fresnel[i]->stack);
        e["fresnel"] = fresnel_name(s.fresnel);
        const auto* model = std::get_if<ModelFresnel>(&s.fresnel);
        e["params"] = model ? Json(to_string(model->parameters)) : Json(nullptr);
        e["mode"] = to_string(s.reflection);
        e["strategy"] = impostor ? Json(to_string(s.strategy)) : Json(nullptr);
        e["iterations"] = impostor ? s.iterations : 0;
        const bool searches = impostor && (s.strategy == Strategy::illinois || s.strategy == Strategy::safe_secant);
        e["search_steps"] = searches ? s.search_steps : 0;
        e["tolerance"] = impostor ? Json(s.tolerance) : Json(nullptr);
        e["rmse"] = errors[i].rmse;  // NaN (null) when no pixel shows the sphere
        // null: no frame with the exact curves was made (no sphere of the scene uses a model)
        e["fit_rmse"] = fit_reference ? Json(fit_errors[i].rmse) : Json(nullptr);
        e["de2000_mean"] = delta_e[i].mean;  // NaN (null) when no pixel shows the sphere
        e["de2000_p95"] = delta_e[i].p95;
        e["mean_abs"] = errors[i].mean_abs;
        e["pixels"] = errors[i].pixels;
        e["mean_iterations"] = impostor ? Json(effort[i].mean_iterations) : Json(nullptr);
        e["mean_rho_error"] = impostor ? Json(effort[i].mean_rho_error) : Json(nullptr);
        e["roughness"] = s.roughness;
        e["glossy"] = s.rough() ? Json(to_string(s.glossy)) : Json(nullptr);
        e["glossy_asked"] = s.rough() ? Json(to_string(s.glossy_request)) : Json(nullptr);
        e["localized_size"] = s.rough() && s.glossy == GlossyMethod::localized ? Json(s.localized_size) : Json(nullptr);
        e["reference_noise"] = s.rough() ? noise[i] : 0.0;  // NaN (null) when no pixel shows the sphere
        // max_bounces > 1 only (a one-bounce scene's metrics.json is as before, byte for byte)
        if (bounce_orders) e["bounce_orders"] = bounce_orders->at(i);
        j["spheres"].push_back(e);
    }
    for (const auto& [key, figures] : effect_metrics) j[key] = *figures;
    return j;
}

class MetricsEffect final : public Effect {
public:
    std::string_view name() const override { return "metrics"; }

    void add_output_passes(PreviewGraph& g) const override {
        auto& graph = g.graph;
        const Scene& scene = g.scene;
        PreviewRun* run = g.run;
        PreviewHandles& h = g.handles;
        const FrameInputs& frame = g.frame;
        h.difference = graph
                           .add_pass<Out<Image>>(
                               {"difference", "|beauty − reference| per pixel", Processor::cpu},
                               [&](Builder& b, Out<Image>& d) {
                                   b.read(h.beauty);
                                   b.read(h.reference);
                                   d.out = b.produce<Image>("difference-image");
                               },
                               [beauty = h.beauty, reference = h.reference](const Out<Image>& d, Resources& r) {
                                   r.emplace(d.out, absolute_difference(r.get(beauty), r.get(reference).image));
                               })
                           .out;
        h.frame_times = graph
                            .add_pass<Out<FrameTimes>>(
                                {"timing",
                                 "ms per frame: median of " + std::to_string(scene.outputs.timing_frames) +
                                     " frames between glFinish calls",
                                 Processor::gpu},
                                [&](Builder& b, Out<FrameTimes>& d) {
                                    frame.declare(b);
                                    d.out = b.produce<FrameTimes>("frame-times");
                                },
                                [run, frame](const Out<FrameTimes>& d, Resources& r) {
                                    r.emplace(d.out, (frame.bind(run->renderer(), r),
                                                      run->renderer().time_frames(run->scene.outputs.timing_frames)));
                                })
                            .out;
        h.metrics =
            graph
                .add_pass<Out<Json>>(
                    {"metrics", "per sphere: RMSE and mean |difference| of linear radiance inside the sphere mask",
                     Processor::cpu},
                    [&](Builder& b, Out<Json>& d) {
                        b.read(h.beauty);
                        b.read(h.reference);
                        b.read(h.localization);
                        if (h.reference_standard_error) b.read(*h.reference_standard_error);
                        if (h.fit_reference) b.read(*h.fit_reference);
                        if (h.bounce_orders) b.read(*h.bounce_orders);
                        for (const auto& [key, handle] : h.effect_metrics) b.read(handle);
                        d.out = b.produce<Json>("metrics");
                    },
                    [run, h](const Out<Json>& d, Resources& r) {
                        std::vector<std::pair<std::string, const Json*>> effect_metrics;
                        for (const auto& [key, handle] : h.effect_metrics)
                            effect_metrics.push_back({key, &r.get(handle)});
                        r.emplace(d.out, metrics_json(
                                             *run, r.get(h.beauty), r.get(h.reference), r.get(h.localization),
                                             h.reference_standard_error ? &r.get(*h.reference_standard_error) : nullptr,
                                             h.fit_reference ? &r.get(*h.fit_reference) : nullptr,
                                             h.bounce_orders ? &r.get(*h.bounce_orders) : nullptr, effect_metrics));
                    })
                .out;
    }
};

}  // namespace

const Effect& metrics_effect() {
    static const MetricsEffect effect;
    return effect;
}

}  // namespace metalfit::glpreview
