#include "lights_effect.hpp"

#include <algorithm>
#include <cmath>
#include <numbers>
#include <optional>
#include <random>

#include "cpu_lights.hpp"
#include "glpreview/gl/saved_gl_state.hpp"
#include "glpreview/gl/uniforms.hpp"
#include "glpreview/render/frame_inputs.hpp"
#include "glpreview/render/gpu_renderer.hpp"
#include "glpreview/render/preview_passes.hpp"
#include "libfit/base/text.hpp"
#include "light.hpp"
#include "render/embedded_shaders.hpp"
#include "shadow_maps.hpp"

namespace metalfit::glpreview {
namespace {

using graph::Builder;
using graph::Handle;
using graph::Processor;
using graph::Resources;

const Lights* lights_of(const Scene& scene) {
    const Lights* lights = scene.effects.find<Lights>();
    return lights && !lights->lights.empty() ? lights : nullptr;
}

bool has_sphere_light(const Lights& lights) {
    return std::any_of(lights.lights.begin(), lights.lights.end(),
                       [](const Light& l) { return l.type == LightType::sphere; });
}

// The shadow maps the renderer made itself (no graph: tests, benchmarks).
struct OwnShadowMaps {
    std::optional<ShadowMaps> maps;
};

class LightsEffect final : public Effect {
public:
    std::string_view name() const override { return "lights"; }

    std::vector<const char*> scene_keys() const override { return {"lights"}; }
    void read_scene(const SceneReader& top, Scene& scene) const override {
        if (top.has("lights")) scene.effects.set(read_lights(top));
    }
    void check_scene(const SceneReader& top, const Scene& scene) const override {
        if (const Lights* lights = lights_of(scene)) check_lights(top, scene, *lights);
    }

    void declare_environment_program(const Scene& scene, ShaderBuilder& builder) const override {
        const Lights* lights = lights_of(scene);
        if (!lights) return;
        builder.define("ENVIRONMENT_LIGHTING", "lights_on_surface")
            .source(shader_text("lights.glsl"))
            .sampler("u_shadow_cubes")
            .sampler("u_shadow_planes");
        if (has_sphere_light(*lights)) builder.define("REFLECTED_EMITTER", "lights_emitter");
    }

    void declare_sphere(const SphereShader& shader, ShaderBuilder& builder) const override {
        if (!lights_of(shader.scene) || !shader.sphere.rough() || shader.diagnostics) return;
        // Mirrors get no highlight of a point, spot or directional light (a set of measure zero) and see sphere
        // lights through REFLECTED_EMITTER; rough spheres add the lights' direct specular to their lobe.
        builder.source(shader_text("ggx.glsl"))
            .source(shader_text("lights_specular.glsl"))
            .add_radiance("lights_specular(p, N, -d, u_roughness)");
    }

    void set_program_uniforms(const Scene& scene, GLuint p) const override {
        const Lights* lights = lights_of(scene);
        if (!lights) return;
        const ShadowLayout layout = shadow_layout(scene, *lights);
        set_uniform(p, "u_light_count", static_cast<int>(lights->lights.size()));
        for (std::size_t i = 0; i < lights->lights.size(); ++i) {
            const Light& light = lights->lights[i];
            const auto name = [i](const char* array) { return std::string(array) + "[" + std::to_string(i) + "]"; };
            set_uniform(p, name("u_light_type").c_str(), static_cast<int>(light.type));
            set_uniform(p, name("u_light_position").c_str(), light.position);
            set_uniform(p, name("u_light_direction").c_str(), light.direction);
            set_uniform(p, name("u_light_power").c_str(), light.power());
            set_uniform(p, name("u_light_radius").c_str(), static_cast<float>(light.radius));
            const double to_radians = std::numbers::pi / 180;
            const double cos_outer = std::cos(light.cone_outer_deg * to_radians);
            const double cos_inner =
                std::max(std::cos(light.cone_inner_deg * to_radians), cos_outer + 1e-6);  // as spot_weight
            glProgramUniform2f(p, glGetUniformLocation(p, name("u_light_cone").c_str()), static_cast<float>(cos_outer),
                               static_cast<float>(cos_inner));
            set_uniform(p, name("u_light_shadow").c_str(), layout.layer[i]);
            if (!light.local()) {
                const ShadowPlane plane = shadow_plane(scene.environment.room, light);
                set_uniform(p, name("u_shadow_plane_origin").c_str(), plane.origin);
                set_uniform(p, name("u_shadow_plane_u").c_str(), plane.axis_u);
                set_uniform(p, name("u_shadow_plane_v").c_str(), plane.axis_v);
            }
        }
    }

    void bind_environment_program(GpuRenderer& renderer, const BuiltProgram& program) const override {
        const Lights* lights = lights_of(renderer.scene());
        if (!lights || !program.reads("u_shadow_cubes")) return;
        const ShadowMaps* maps = renderer.frame().find<ShadowMaps>();
        if (!maps) {  // no graph handed them over: made here once, the frame's GL state kept
            auto& own = renderer.frame().state<OwnShadowMaps>();
            if (!own.maps) {
                const SavedGlState saved;
                const ShadowLayout layout = shadow_layout(renderer.scene(), *lights);
                own.maps = ShadowMaps::create({kShadowMapSize, layout.cubes, layout.planes});
                render_shadow_maps(renderer, *lights, layout, *own.maps);
            }
            maps = &*own.maps;
        }
        program.bind("u_shadow_cubes", maps->cubes.id());
        program.bind("u_shadow_planes", maps->planes.id());
    }

    void add_frame_input_passes(PreviewGraph& g) const override {
        const Lights* lights = lights_of(g.scene);
        if (!lights) return;  // a scene without lights plans exactly the passes it did before lights existed
        const ShadowLayout layout = shadow_layout(g.scene, *lights);
        std::vector<std::string> why;
        for (std::size_t i = 0; i < lights->lights.size(); ++i)
            why.push_back("light " + std::to_string(i) + " (" + to_string(lights->lights[i].type) +
                          "): " + layout.why[i]);
        if (layout.cubes + layout.planes == 0) {
            g.graph.skip("shadow-maps", join(why, "; "));
            return;
        }
        struct Data {
            Handle<ShadowMaps> out;
        };
        PreviewRun* run = g.run;
        const Handle<ShadowMaps> maps =
            g.graph
                .add_pass<Data>(
                    {"shadow-maps",
                     join(why, "; ") + "; distances to the first sphere or room box, sampled with PCSS by the capture, "
                                       "the background and the rough spheres",
                     Processor::gpu},
                    [&](Builder& b, Data& d) {
                        b.read(g.in.environment);
                        d.out = b.create<ShadowMaps>("shadow-maps", {kShadowMapSize, layout.cubes, layout.planes});
                    },
                    [run, lights = *lights, layout](const Data& d, Resources& r) {
                        render_shadow_maps(run->renderer(), lights, layout, r.get(d.out));
                    })
                .out;
        g.frame.add(maps);
        g.environment.add(maps);
    }

    bool lights_cpu_reference(const Scene& scene) const override { return lights_of(scene) != nullptr; }
    RGB cpu_surface_light(const Scene& scene, const RGB& albedo, Vec3 p, Vec3 n) const override {
        return light_on_surface(scene, *lights_of(scene), albedo, p, n);
    }
    std::optional<RGB> cpu_emitter(const Scene& scene, Vec3 origin, Vec3 dir) const override {
        return emitter_seen(*lights_of(scene), origin, dir);
    }
    RadianceEstimate cpu_sphere_light(const Scene& scene, std::size_t sphere, Vec3 p, Vec3 n, Vec3 v,
                                      const SphereFresnel& fresnel, int samples, std::uint64_t seed) const override {
        return specular_from_lights(scene, *lights_of(scene), sphere, p, n, v, fresnel, samples, seed);
    }
};

}  // namespace

const Effect& lights_effect() {
    static const LightsEffect effect;
    return effect;
}

}  // namespace metalfit::glpreview
