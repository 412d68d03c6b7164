#include "caustics_effect.hpp"

#include <numbers>
#include <optional>

#include "../rings/ring.hpp"
#include "caustic_maps.hpp"
#include "caustic_metrics.hpp"
#include "caustic_reference.hpp"
#include "caustic_settings.hpp"
#include "glpreview/gl/uniforms.hpp"
#include "glpreview/render/frame_inputs.hpp"
#include "glpreview/render/gpu_renderer.hpp"
#include "glpreview/render/preview_passes.hpp"
#include "render/embedded_shaders.hpp"

namespace metalfit::glpreview {
namespace {

using graph::Builder;
using graph::Handle;
using graph::Processor;
using graph::Resources;

// The light maps the renderer made itself (no graph: tests, benchmarks).
struct OwnLightMaps {
    std::optional<RoomLightMaps> maps;
};

class CausticsEffect final : public Effect {
public:
    std::string_view name() const override { return "caustics"; }

    std::vector<const char*> scene_keys() const override { return {"caustics"}; }
    void read_scene(const SceneReader& top, Scene& scene) const override {
        if (top.has("caustics")) scene.effects.set(read_caustic_settings(top));
    }

    void declare_environment_program(const Scene& scene, ShaderBuilder& builder) const override {
        if (plan_caustics(scene).jobs.empty()) return;
        builder.define("ENVIRONMENT_CAUSTICS", "caustics_on_surface")
            .source(shader_text("room_face.glsl"))
            .source(shader_text("caustics.glsl"))
            .sampler("u_caustic_light");
    }

    void set_program_uniforms(const Scene& scene, GLuint p) const override {
        if (plan_caustics(scene).jobs.empty()) return;
        set_uniform(p, "u_caustic_room_min", scene.environment.room.min);
        set_uniform(p, "u_caustic_room_max", scene.environment.room.max);
    }

    void bind_environment_program(GpuRenderer& renderer, const BuiltProgram& program) const override {
        if (!program.reads("u_caustic_light") || making_caustics(renderer)) return;  // not while they are made
        const RoomLightMaps* maps = renderer.frame().find<RoomLightMaps>(kCausticLightName);
        if (!maps) {  // no graph handed them over: made here once
            auto& own = renderer.frame().state<OwnLightMaps>();
            if (!own.maps) {
                const CausticSettings settings = caustic_settings(renderer.scene());
                own.maps = RoomLightMaps::create({settings.light_map_size});
                render_caustic_light_maps(renderer, plan_caustics(renderer.scene()), settings, *own.maps);
            }
            maps = &*own.maps;
        }
        program.bind("u_caustic_light", maps->texture.id());
    }

    void add_frame_input_passes(PreviewGraph& g) const override {
        const CausticPlan plan = plan_caustics(g.scene);
        if (plan.jobs.empty()) {
            if (g.scene.effects.find<Rings>()) g.graph.skip("caustic-maps", plan.why);
            return;  // a scene without rings plans exactly the passes it did before caustics existed
        }
        const CausticSettings settings = caustic_settings(g.scene);
        struct Data {
            Handle<RoomLightMaps> out;
        };
        PreviewRun* run = g.run;
        const Handle<RoomLightMaps> maps =
            g.graph
                .add_pass<Data>(
                    {"caustic-maps",
                     plan.why + "; " + std::to_string(settings.map_size) +
                         "² photons per light and ring, reflected "
                         "by the ring and landed by the distance impostor in the room's distance cube, "
                         "splatted (Gaussian σ " +
                         glsl_float(settings.filter_width) + " m) into six " + std::to_string(settings.light_map_size) +
                         "² light maps",
                     Processor::gpu},
                    [&](Builder& b, Data& d) {
                        b.read(g.in.environment);
                        d.out = b.create<RoomLightMaps>("caustic-light-maps", {settings.light_map_size});
                    },
                    [run, plan, settings](const Data& d, Resources& r) {
                        render_caustic_light_maps(run->renderer(), plan, settings, r.get(d.out));
                    })
                .out;
        g.frame.add(maps, kCausticLightName);
        g.environment.add(maps, kCausticLightName);
        g.handles.room_light_maps[kCausticLightName] = maps;
    }

    // metrics.json's "caustics": the reference photon map's budget, receivers and focus, and the GPU's light maps
    // against it ("gpu").
    void add_output_passes(PreviewGraph& g) const override {
        const auto maps = g.handles.room_light_maps.find(kCausticLightName);
        if (maps == g.handles.room_light_maps.end() || !g.scene.outputs.metrics) return;
        const Handle<RoomLightMaps> light_maps = maps->second;
        PreviewRun* run = g.run;
        const Scene& scene = g.scene;
        const Handle<Json> figures =
            g.graph
                .add_pass<graph::Out<Json>>(
                    {"caustic-figures",
                     "metrics.json's caustics: the photon-traced reference's power, peaks and focus, and the GPU's "
                     "light maps against it",
                     Processor::cpu},
                    [&](Builder& b, graph::Out<Json>& d) {
                        b.read(light_maps);
                        b.read(g.in.materials);
                        d.out = b.produce<Json>("caustic-figures");
                    },
                    [run, &scene, light_maps](const graph::Out<Json>& d, Resources& r) {
                        Json j;
                        if (const CausticMap* map = reference_caustic_map(scene)) {
                            const RoomLightMaps& gpu = r.get(light_maps);
                            j = caustic_metrics_json(scene, *map, run->luminance);
                            j["gpu"] = gpu_caustic_metrics_json(scene, *map, read_room_light_maps(gpu), gpu.size,
                                                                run->luminance);
                        }
                        r.emplace(d.out, std::move(j));
                    })
                .out;
        g.handles.effect_metrics.push_back({"caustics", figures});
    }

    // --- The CPU reference (the photon tracer) ---
    // The rings' exact spectral Fresnel, resolved with the materials when a CPU reference is asked for; the photon map
    // is traced on the first cpu_surface_light (once, whichever thread comes first) and lights the room's faces with
    // albedo/π × E_caustic, as ENVIRONMENT_CAUSTICS does on the GPU.
    void resolve_materials(Scene& scene, FresnelLibrary& library) const override {
        resolve_caustic_spectra(scene, library);
    }
    bool lights_cpu_reference(const Scene& scene) const override {
        return has_caustics(scene) && scene.effects.find<CausticSpectra>();
    }
    RGB cpu_surface_light(const Scene& scene, const RGB& albedo, Vec3 p, Vec3 n) const override {
        const CausticMap* map = reference_caustic_map(scene);
        if (!map) return {0, 0, 0};
        const RGB e = map->irradiance_at(scene.environment.room, p, n);
        return (1.0 / std::numbers::pi) * RGB{albedo.r * e.r, albedo.g * e.g, albedo.b * e.b};
    }
};

}  // namespace

const Effect& caustics_effect() {
    static const CausticsEffect effect;
    return effect;
}

}  // namespace metalfit::glpreview
