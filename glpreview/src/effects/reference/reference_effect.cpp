#include "reference_effect.hpp"

#include <optional>

#include "glpreview/effects/bounces.hpp"
#include "glpreview/effects/registry.hpp"
#include "glpreview/render/bounce_orders.hpp"
#include "glpreview/render/cpu_reference.hpp"
#include "glpreview/render/environment.hpp"
#include "glpreview/render/frame_inputs.hpp"
#include "glpreview/render/monte_carlo_reference.hpp"
#include "glpreview/render/preview_passes.hpp"
#include "libfit/base/text.hpp"

namespace metalfit::glpreview {
namespace {

using graph::Builder;
using graph::Handle;
using graph::Out;
using graph::Processor;
using graph::Resources;

// What the registered effects add to the references of `scene` (lights), or nothing.
std::optional<CpuLighting> cpu_lighting(const Scene& scene) {
    std::vector<const Effect*> lighting;
    for (const Effect* effect : all_effects())
        if (effect->lights_cpu_reference(scene)) lighting.push_back(effect);
    if (lighting.empty()) return std::nullopt;
    CpuLighting all;
    all.surface = [&scene, lighting](const RGB& albedo, Vec3 p, Vec3 n) {
        RGB sum{0, 0, 0};
        for (const Effect* effect : lighting) sum = sum + effect->cpu_surface_light(scene, albedo, p, n);
        return sum;
    };
    all.emitter = [&scene, lighting](Vec3 origin, Vec3 dir) -> std::optional<RGB> {
        for (const Effect* effect : lighting)
            if (const std::optional<RGB> emitted = effect->cpu_emitter(scene, origin, dir)) return emitted;
        return std::nullopt;
    };
    all.objects = [&scene, lighting](Vec3 o, Vec3 d, double t_max,
                                     const EnvironmentTracer& room) -> std::optional<EnvironmentHit> {
        std::optional<EnvironmentHit> nearest;
        for (const Effect* effect : lighting)
            if (std::optional<EnvironmentHit> seen =
                    effect->cpu_environment_object(scene, o, d, nearest ? nearest->t : t_max, room))
                nearest = seen;
        return nearest;
    };
    all.sphere_light = [&scene, lighting](std::size_t sphere, Vec3 p, Vec3 n, Vec3 v, const SphereFresnel& fresnel,
                                          int samples, std::uint64_t seed) {
        RadianceEstimate sum;
        for (const Effect* effect : lighting) {
            const RadianceEstimate e = effect->cpu_sphere_light(scene, sphere, p, n, v, fresnel, samples, seed);
            sum.mean = sum.mean + e.mean;
            sum.variance = sum.variance + e.variance;
        }
        return sum;
    };
    return all;
}

// The references' environment: the room with the light and the objects effects add to it.
EnvironmentTracer reference_tracer(const Scene& scene, const std::optional<CpuLighting>& lighting,
                                   const Image* equirect) {
    return EnvironmentTracer(scene.environment, equirect, lighting ? lighting->surface : SurfaceLight{},
                             lighting ? lighting->objects : EnvironmentObjects{});
}

class ReferenceEffect final : public Effect {
public:
    std::string_view name() const override { return "reference"; }

    void add_output_passes(PreviewGraph& g) const override {
        auto& graph = g.graph;
        const Scene& scene = g.scene;
        const Features& f = g.features;
        const SceneInputs& in = g.in;
        PreviewRun* run = g.run;
        PreviewHandles& h = g.handles;
        // cpu-reference: the ground truth.
        h.reference =
            graph
                .add_pass<Out<ReferenceRender>>(
                    {"cpu-reference",
                     max_bounces(scene) > 1
                         ? "analytic ray tracing of the same scene: exact mirror reflections between the spheres, up to " +
                               std::to_string(max_bounces(scene)) + " bounces, same Fresnel, same camera"
                         : "analytic ray tracing of the same scene: exact mirror reflections, same Fresnel, same camera",
                     Processor::cpu},
                    [&](Builder& b, Out<ReferenceRender>& d) {
                        b.read(in.camera);
                        if (h.environment.equirect_image) b.read(*h.environment.equirect_image);
                        if (h.luts) b.read(*h.luts);
                        if (h.parameters) b.read(*h.parameters);
                        d.out = b.produce<ReferenceRender>("reference-image");
                    },
                    [run, equirect = h.environment.equirect_image](const Out<ReferenceRender>& d, Resources& r) {
                        const std::optional<CpuLighting> lighting = cpu_lighting(run->scene);
                        const EnvironmentTracer tracer =
                            reference_tracer(run->scene, lighting, equirect ? &r.get(*equirect) : nullptr);
                        r.emplace(d.out, render_reference(run->scene, run->fresnel, tracer, run->threads,
                                                          lighting ? &*lighting : nullptr, max_bounces(run->scene)));
                    })
                .out;
        // monte-carlo-reference: the rough spheres' lobes by Monte Carlo, over the analytic reference's pixels.
        if (f.monte_carlo_reference) {
            struct Data {
                Handle<ReferenceRender> analytic, out;
                Handle<Image> standard_error;
            };
            std::vector<std::string> rough;
            for (std::size_t i = 0; i < scene.spheres.size(); ++i)
                if (scene.spheres[i].rough()) rough.push_back(std::to_string(i));
            const Data& mc = graph.add_pass<Data>(
                {"monte-carlo-reference",
                 "sphere(s) " + join(rough) + " rough: the GGX lobe by Monte Carlo (" +
                     std::to_string(scene.outputs.reference_samples) +
                     " visible-normal samples per pixel, fixed seed), exact reflected rays, same Fresnel; standard error beside it",
                 Processor::cpu},
                [&](Builder& b, Data& d) {
                    b.read(in.camera);
                    if (h.environment.equirect_image) b.read(*h.environment.equirect_image);
                    d.analytic = b.read(h.reference);
                    d.out = b.produce<ReferenceRender>("monte-carlo-reference-image");
                    d.standard_error = b.produce<Image>("reference-standard-error");
                },
                [run, equirect = h.environment.equirect_image](const Data& d, Resources& r) {
                    const std::optional<CpuLighting> lighting = cpu_lighting(run->scene);
                    const EnvironmentTracer tracer =
                        reference_tracer(run->scene, lighting, equirect ? &r.get(*equirect) : nullptr);
                    MonteCarloReference result = render_monte_carlo_reference(
                        run->scene, run->fresnel, tracer, r.get(d.analytic), run->scene.outputs.reference_samples,
                        run->threads, lighting ? &*lighting : nullptr, max_bounces(run->scene));
                    r.emplace(d.out, std::move(result.render));
                    r.emplace(d.standard_error, std::move(result.standard_error));
                });
            h.reference = mc.out;
            h.reference_standard_error = mc.standard_error;
        } else {
            graph.skip("monte-carlo-reference", f.cpu_reference
                                                    ? "every sphere is a mirror: the analytic reference is exact"
                                                    : "no reference, difference or metrics asked for");
        }
        if (max_bounces(scene) > 1) add_bounce_orders_pass(g);
    }

private:
    // bounce-orders: per order k = 1 … max_bounces the CPU references cut at k bounces with the spheres' own
    // Fresnel, the reference LUTs and the spectral Fresnel, and their errors per sphere (render/bounce_orders.hpp).
    static void add_bounce_orders_pass(PreviewGraph& g) {
        const SceneInputs& in = g.in;
        PreviewRun* run = g.run;
        PreviewHandles& h = g.handles;
        const int orders = max_bounces(g.scene);
        g.handles.bounce_orders =
            g.graph
                .add_pass<Out<Json>>(
                    {"bounce-orders",
                     "max_bounces " + std::to_string(orders) + ": per bounce order 1-" + std::to_string(orders) +
                         " the mirror paths cut there, with each sphere's own Fresnel, the reference LUTs (RGB) and "
                         "the exact spectral Fresnel (spectral); per sphere the model, RGB-vs-spectral and total error",
                     Processor::cpu},
                    [&](Builder& b, Out<Json>& d) {
                        b.read(in.camera);
                        if (h.environment.equirect_image) b.read(*h.environment.equirect_image);
                        if (h.luts) b.read(*h.luts);
                        if (h.parameters) b.read(*h.parameters);
                        d.out = b.produce<Json>("bounce-order-errors");
                    },
                    [run, orders, equirect = h.environment.equirect_image](const Out<Json>& d, Resources& r) {
                        const std::optional<CpuLighting> lighting = cpu_lighting(run->scene);
                        const EnvironmentTracer tracer =
                            reference_tracer(run->scene, lighting, equirect ? &r.get(*equirect) : nullptr);
                        BounceFresnel fresnel{run->fresnel, run->reference_fresnel, {}, run->uplift.get()};
                        for (const auto& s : run->spectral) fresnel.spectral.push_back(s.get());
                        const std::size_t spheres = run->scene.spheres.size();
                        std::vector<std::vector<SphereOrderError>> errors;
                        for (int k = 1; k <= orders; ++k)
                            errors.push_back(
                                bounce_order_errors(render_bounce_order(run->scene, fresnel, tracer, k, run->threads,
                                                                        lighting ? &*lighting : nullptr),
                                                    spheres, run->delta_e));
                        Json& out = r.emplace(d.out, Json::array());
                        for (std::size_t i = 0; i < spheres; ++i) out.push_back(bounce_orders_json(errors, i));
                    })
                .out;
    }
};

}  // namespace

const Effect& reference_effect() {
    static const ReferenceEffect effect;
    return effect;
}

}  // namespace metalfit::glpreview
