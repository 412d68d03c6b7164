// An effect of the preview as one unit (docs/pass-graph.md, "Adding an effect"): what it adds to the sphere shader,
// what it binds for each sphere it draws, the passes it adds to a preview graph (with the skips --explain lists) and
// what it derives from a captured environment when there is no graph (tests, benchmarks). Each effect is one folder
// glpreview/src/effects/<effect>/ (its code and its GLSL) and one line of the registry (effects/registry.hpp); the
// renderer and the preview's graph call every registered effect and name none.
#pragma once

#include <limits>
#include <optional>
#include <string_view>
#include <vector>

#include "glpreview/graph/pass_graph.hpp"
#include "glpreview/render/blackboard.hpp"
#include "glpreview/render/cpu_lighting.hpp"
#include "glpreview/render/features.hpp"
#include "glpreview/render/shader_builder.hpp"
#include "glpreview/scene/scene.hpp"
#include "glpreview/scene/scene_keys.hpp"
#include "glpreview/scene/scene_reader.hpp"

namespace metalfit::glpreview {

class GpuRenderer;
class FrameInputs;
class FresnelLibrary;
struct EnvironmentCube;
struct PreviewHandles;
struct PreviewRun;
struct SceneInputs;
struct SphereFresnel;

// The sphere shader being assembled for one sphere of a scene: `fresnel` resolves its model (null while planning,
// when only the variant's name is wanted); `diagnostics`: the localization frame.
struct SphereShader {
    const Scene& scene;
    const Sphere& sphere;
    const SphereFresnel* fresnel = nullptr;
    bool diagnostics = false;
};

// One sphere drawn in a frame: its program (with the units its builder assigned) and the frame's shared state.
struct SphereDraw {
    const Scene& scene;
    const Sphere& sphere;
    const SphereFresnel& fresnel;
    const BuiltProgram& program;
    GpuRenderer& renderer;
};

// The preview graph being built: effects add their passes here, hand what every GPU frame reads to `frame` and
// publish what later passes and the caller read in `handles` (the graph's blackboard of handles).
struct PreviewGraph {
    graph::PassGraph& graph;
    const Scene& scene;
    const Features& features;
    const SceneInputs& in;
    PreviewRun* run;  // null: compile and explain only
    FrameInputs& frame;
    FrameInputs& environment;  // what the capture of the environment reads (added before the capture pass)
    PreviewHandles& handles;
};

// An effect reads its own scene keys (SceneKeys: scene_keys, read_scene, sphere_keys, read_sphere, check_scene).
class Effect : public SceneKeys {
public:
    virtual ~Effect() = default;
    virtual std::string_view name() const = 0;
    // Adds this effect's defines, GLSL, samplers and lobe to `builder` where it applies to the sphere.
    virtual void declare_sphere(const SphereShader&, ShaderBuilder&) const {}
    // Sets this effect's uniforms and binds its textures for one sphere's draw.
    virtual void bind_sphere(const SphereDraw&) const {}
    // Adds this effect's passes to a preview graph (or the skips that say why none runs): those the frame reads,
    // before the beauty frame, and those that read the beauty frame (references, diagnostics, metrics), after it.
    virtual void add_frame_input_passes(PreviewGraph&) const {}
    virtual void add_output_passes(PreviewGraph&) const {}
    // What this effect adds to every program that reads the environment (the capture, the background, the spheres):
    // its GLSL (ENVIRONMENT_LIGHTING: light on the room's surfaces; REFLECTED_EMITTER: emitters that camera and
    // mirror rays see), samplers and defines; and what it binds for such a program at each use.
    virtual void declare_environment_program(const Scene&, ShaderBuilder&) const {}
    virtual void bind_environment_program(GpuRenderer&, const BuiltProgram&) const {}
    // Sets the uniforms this effect's GLSL reads that do not change while the renderer lives, on a program's first
    // use by a renderer (uniforms a program lacks are ignored).
    virtual void set_program_uniforms(const Scene&, GLuint /*program*/) const {}
    // The CPU references: what this effect adds (render/cpu_lighting.hpp), for one scene. Thread-safe: the
    // references call them from several threads.
    virtual RGB cpu_surface_light(const Scene&, const RGB& /*albedo*/, Vec3 /*p*/, Vec3 /*n*/) const {
        return {0, 0, 0};
    }
    virtual std::optional<RGB> cpu_emitter(const Scene&, Vec3 /*origin*/, Vec3 /*dir*/) const { return std::nullopt; }
    virtual RadianceEstimate cpu_sphere_light(const Scene&, std::size_t /*sphere*/, Vec3 /*p*/, Vec3 /*n*/, Vec3 /*v*/,
                                              const SphereFresnel&, int /*samples*/, std::uint64_t /*seed*/) const {
        return {};
    }
    // An object this effect stands in the room that the ray o + t d (d unit) meets before t_max, the room's own hit:
    // its radiance and ray parameter, as ENVIRONMENT_OBJECT on the GPU (environment.glsl); `room` traces the room
    // alone (EnvironmentTracer::room_trace, with the light effects add to its surfaces).
    virtual std::optional<EnvironmentHit> cpu_environment_object(const Scene&, Vec3 /*o*/, Vec3 /*d*/, double /*t_max*/,
                                                                 const EnvironmentTracer& /*room*/) const {
        return std::nullopt;
    }
    // Where a shadow ray from o along unit d first meets an object of this effect (ENVIRONMENT_OCCLUDER), past a
    // small epsilon; ∞ when it meets none. The lights' CPU shadow rays (cpu_lights' occluded) ask every effect.
    virtual double cpu_occluder(const Scene&, Vec3 /*o*/, Vec3 /*d*/) const {
        return std::numeric_limits<double>::infinity();
    }
    // Whether this effect adds anything to the CPU references of `scene` (else its cpu_* are not called).
    virtual bool lights_cpu_reference(const Scene&) const { return false; }
    // The objects this effect adds to the room that cast shadows (ENVIRONMENT_OCCLUDER on the GPU), by their bounds:
    // the lights plan their shadow maps with them.
    virtual std::vector<BoundingSphere> shadow_casters(const Scene&) const { return {}; }
    // Resolves what this effect's own scene objects need from the materials (a ring's Fresnel) into the scene's
    // settings (Scene::effects), before a preview plans its passes (resolve_effect_materials, render/preview.hpp).
    virtual void resolve_materials(Scene& /*scene*/, FresnelLibrary& /*library*/) const {}
    // Without a graph: derives this effect's inputs from the renderer's own captured cube (GpuRenderer::capture_environment()).
    virtual void derive_from_environment(GpuRenderer&, const EnvironmentCube&) const {}
    // Lets go of what this effect's frame state keeps for a Fresnel (textures uploaded for it, keyed by its address),
    // before that Fresnel is destroyed (GpuRenderer::forget_fresnel: the sheet's rows, each made and let go).
    virtual void forget_fresnel(GpuRenderer&, const SphereFresnel&) const {}
};

}  // namespace metalfit::glpreview
