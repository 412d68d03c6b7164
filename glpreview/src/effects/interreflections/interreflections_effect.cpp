#include "interreflections_effect.hpp"

#include <algorithm>
#include <optional>
#include <stdexcept>
#include <string>

#include "bounce_maps.hpp"
#include "bounce_plan.hpp"
#include "glpreview/effects/bounces.hpp"
#include "glpreview/gl/uniforms.hpp"
#include "glpreview/render/frame_inputs.hpp"
#include "glpreview/render/preview_passes.hpp"
#include "render/embedded_shaders.hpp"

namespace metalfit::glpreview {

int max_bounces(const Scene& scene) {
    const Interreflections* settings = scene.effects.find<Interreflections>();
    return settings ? settings->max_bounces : 1;
}

namespace {

using graph::Builder;
using graph::Out;
using graph::Resources;

// The maps the renderer made itself (no graph: tests, benchmarks).
struct OwnBounceMaps {
    std::optional<BounceMaps> maps;
};

// The bounces' Fresnel table, remade when the spheres' Fresnel changes (the frame with the exact curves).
struct BounceFresnelTexture {
    std::vector<const SphereFresnel*> made_for;
    std::optional<gl::Texture> table;

    GLuint texture(const GpuRenderer& renderer) {
        std::vector<const SphereFresnel*> now;
        for (std::size_t j = 0; j < renderer.scene().spheres.size(); ++j) now.push_back(&renderer.fresnel(j));
        if (!table || now != made_for) {
            table = bounce_fresnel_table(renderer);
            made_for = now;
        }
        return table->id();
    }
};

std::size_t sphere_index(const Scene& scene, const Sphere& sphere) {
    return static_cast<std::size_t>(&sphere - scene.spheres.data());
}

class InterreflectionsEffect final : public Effect {
public:
    std::string_view name() const override { return "interreflections"; }

    std::vector<const char*> scene_keys() const override { return {"max_bounces"}; }
    void read_scene(const SceneReader& top, Scene& scene) const override {
        if (!top.has("max_bounces")) return;
        Interreflections settings;
        top.read("max_bounces", settings.max_bounces, 1, kMaxBounces);
        if (settings.max_bounces > 1 && !scene.environment.captured())
            top.fail(top.field("max_bounces"),
                     "inter-reflections need a captured environment (room, sphere-room or an equirect with a proxy): "
                     "the spheres' distance maps are taken like its cube");
        scene.effects.set(settings);
    }
    // A mirror sphere searches its own distance map: the distance impostor (with the sphere's strategy), whatever
    // lookup it asked for against the room (a direction alone cannot place a sphere a few radii away).
    void read_sphere(const SceneReader& r, Sphere& s, Scene& scene) const override {
        if (max_bounces(scene) <= 1 || s.reflection == ReflectionMode::distance_impostor) return;
        if (s.rough() && s.glossy != GlossyMethod::prefiltered) return;  // the localized lobe keeps the room
        if (r.has("reflection"))
            scene.warnings.push_back(r.file().string() + ": " + r.field("reflection") + ": '" +
                                     to_string(s.reflection) +
                                     "' becomes 'distance-impostor' with max_bounces > 1: a sphere searches its own "
                                     "map");
        s.reflection = ReflectionMode::distance_impostor;
    }
    // Spheres that reflect each other must not overlap: a ray leaving one would start inside another.
    void check_scene(const SceneReader& top, const Scene& scene) const override {
        if (max_bounces(scene) <= 1) return;
        const auto mirrors = std::count_if(scene.spheres.begin(), scene.spheres.end(),
                                           [](const Sphere& sphere) { return !sphere.rough(); });
        if (mirrors > kMaxMappedSpheres)
            top.fail(top.field("max_bounces"), "at most " + std::to_string(kMaxMappedSpheres) +
                                                   " mirror spheres reflect each other (" + std::to_string(mirrors) +
                                                   " here): each takes three 256² cube-map layers");
        for (std::size_t j = 0; j < scene.spheres.size(); ++j)
            for (std::size_t i = 0; i < j; ++i) {
                const Sphere& a = scene.spheres[i];
                const Sphere& b = scene.spheres[j];
                if (length(b.center - a.center) < a.radius + b.radius)
                    top.fail(top.field("spheres[" + std::to_string(j) + "]"),
                             "overlaps spheres[" + std::to_string(i) +
                                 "]: spheres that reflect each other (max_bounces > 1) must not overlap");
            }
    }

    void declare_sphere(const SphereShader& shader, ShaderBuilder& builder) const override {
        if (shader.diagnostics) return;
        const BouncePlan plan = plan_bounces(shader.scene);
        const std::size_t i = sphere_index(shader.scene, shader.sphere);
        // A rough sphere with a map of its own: its lobe's lookup from its centre in that map (bound below).
        if (plan.maps_rough(i)) builder.define("GLOSSY_OWN_MAP");
        if (!plan.maps(i)) return;
        builder.define("IMPOSTOR_LAYERS")
            .define("MIRROR_REFLECTED", "bounce_radiance")
            .define("MAX_BOUNCES", std::to_string(plan.max_bounces))
            .source(shader_text("bounce.glsl"))
            .sampler("u_impostor_layers")
            .sampler("u_bounce_hits")
            .sampler("u_bounce_fresnel")
            .sampler("u_bounce_spheres");
    }

    void bind_sphere(const SphereDraw& draw) const override {
        const bool mirror = draw.program.reads("u_bounce_hits");
        const bool rough = glGetUniformLocation(draw.program.id(), "u_glossy_origin") >= 0;
        if (!mirror && !rough) return;  // one bounce, a sphere without maps, or the diagnostics
        Blackboard& frame = draw.renderer.frame();
        const BounceMaps* maps = frame.find<BounceMaps>();
        if (!maps && frame.state<OwnBounceMaps>().maps) maps = &*frame.state<OwnBounceMaps>().maps;
        if (rough) {
            const std::size_t i = sphere_index(draw.scene, draw.sphere);
            const RoughMap* own = maps && i < maps->rough.size() && maps->rough[i] ? &*maps->rough[i] : nullptr;
            if (!own) {  // seen in a map being drawn before its own exists: its lobe reflects the room's cube
                set_uniform(draw.program.id(), "u_glossy_origin", draw.scene.environment.reference());
                return;
            }
            draw.program.bind("u_env", own->radiance.texture.id());
            set_uniform(draw.program.id(), "u_glossy_origin", draw.sphere.center);
            draw.program.bind("u_prefiltered", own->prefiltered.texture.id());
            set_uniform(draw.program.id(), "u_prefiltered_levels", static_cast<float>(own->prefiltered.levels));
            return;
        }
        if (!maps) throw std::logic_error("a mirror sphere reflects the others, but their maps were not made");
        draw.program.bind("u_impostor_layers", maps->radiance.id());
        draw.program.bind("u_bounce_hits", maps->hits.id());
        draw.program.bind("u_bounce_spheres", maps->spheres.id());
        draw.program.bind("u_bounce_fresnel", frame.state<BounceFresnelTexture>().texture(draw.renderer));
        set_uniform(draw.program.id(), "u_bounce_sphere", static_cast<int>(sphere_index(draw.scene, draw.sphere)));
        set_uniform(draw.program.id(), "u_bounce_back", maps->layers);
    }

    void add_frame_input_passes(PreviewGraph& g) const override {
        const BouncePlan plan = plan_bounces(g.scene);
        if (!plan.active() || !g.handles.environment.cube) {
            g.graph.skip("sphere-maps", plan.reason);
            return;
        }
        const FrameInputs reads = g.frame;  // what the spheres' programs read (the room's cube, LUTs, lobes)
        PreviewRun* run = g.run;
        const auto maps = g.graph
                              .add_pass<Out<BounceMaps>>(
                                  {"sphere-maps", plan.reason, graph::Processor::gpu},
                                  [&](Builder& b, Out<BounceMaps>& d) {
                                      reads.declare(b);
                                      d.out = b.produce<BounceMaps>("sphere-distance-maps");
                                  },
                                  [run, reads, plan](const Out<BounceMaps>& d, Resources& r) {
                                      reads.bind(run->renderer(), r);
                                      render_bounce_maps(run->renderer(), plan, r.emplace(d.out));
                                  })
                              .out;
        g.frame.add(maps);
    }

    void derive_from_environment(GpuRenderer& renderer, const EnvironmentCube&) const override {
        const BouncePlan plan = plan_bounces(renderer.scene());
        if (!plan.active()) return;
        std::optional<BounceMaps>& own = renderer.frame().state<OwnBounceMaps>().maps;
        render_bounce_maps(renderer, plan, own.emplace());
    }
};

}  // namespace

const Effect& interreflections_effect() {
    static const InterreflectionsEffect effect;
    return effect;
}

}  // namespace metalfit::glpreview
