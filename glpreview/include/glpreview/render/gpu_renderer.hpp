// The GL side of a preview: the frame (background + one draw per sphere, each sphere's program assembled by the
// registered effects), the programs it links, and the blackboard through which the pass graph hands the effects
// their resources. Its jobs are one source file each: gpu_renderer.cpp (programs, the frame, read-back),
// gpu_environment.cpp (the environment capture, and what the effects derive from it without a graph),
// gpu_diagnostics.cpp (the localization frame, cube read-back, frame timing). Needs a current GlContext.
#pragma once

#include <array>
#include <map>
#include <optional>
#include <span>
#include <string>
#include <vector>

#include "glpreview/gl/gl_context.hpp"
#include "glpreview/gl/objects.hpp"
#include "glpreview/gl/program_cache.hpp"
#include "glpreview/io/image.hpp"
#include "glpreview/render/blackboard.hpp"
#include "glpreview/render/features.hpp"
#include "glpreview/render/gpu_resources.hpp"
#include "glpreview/render/shader_builder.hpp"
#include "glpreview/render/sphere_fresnel.hpp"
#include "glpreview/render/sphere_shader.hpp"
#include "glpreview/scene/camera.hpp"
#include "glpreview/scene/scene.hpp"

namespace metalfit::glpreview {

class GpuRenderer {
public:
    // fresnel[i] belongs to scene.spheres[i]; `equirect` is the loaded image for an equirect environment (or null,
    // when the pass graph binds its texture with use_equirect()).
    // The scene's environment, camera and image size are read when the renderer is made and when a program is first
    // linked (their uniforms are set once then); the spheres are read at every frame, so they may move or change
    // their reflection settings and Fresnel kind between frames.
    // `programs`: where its GL programs are linked and kept (the context's, shared with the other renderers made in
    // it); none: a cache of its own.
    GpuRenderer(const Scene& scene, const Features& features, std::vector<const SphereFresnel*> fresnel,
                const Image* equirect, ProgramCache* programs = nullptr);
    GpuRenderer(const GpuRenderer&) = delete;
    GpuRenderer& operator=(const GpuRenderer&) = delete;

    // Replaces sphere i's Fresnel (the scene's sphere must show the same Fresnel: the reference or that model).
    void set_fresnel(std::size_t sphere, const SphereFresnel* fresnel);
    // What every effect keeps for `fresnel` let go (Effect::forget_fresnel), before the caller destroys it: the
    // textures are keyed by its address, which a later Fresnel may reuse.
    void forget_fresnel(const SphereFresnel& fresnel);

    // Ray-casts the environment into `cube` (once; spheres may move afterwards) and reflects it from then on.
    void capture_environment(const EnvironmentCube& cube);
    // The same into a cube map of the renderer's own (tests, benchmarks without a graph), and what every effect
    // derives from it (Effect::derive_from_environment: the prefiltered cube, the downsampled cubes, ...).
    void capture_environment();
    // Reflects an already captured cube / an equirect texture owned by the caller (the pass graph).
    void use_environment(const EnvironmentCube& cube) { cube_ = &cube; }
    void use_equirect(const EquirectTexture& texture) { equirect_ = &texture; }
    // What the effects read at every frame: the graph's resources (put) and their own state (Effect folders).
    Blackboard& frame() { return frame_; }

    Image render();  // one beauty frame, read back
    // The localization diagnostics of the same frame (no background, 0 outside the spheres): per pixel r = the
    // distance impostor's refinement steps taken, g = |ρ − 1| at its lookup point, b = 1 on impostor spheres.
    Image render_localization();
    // One beauty frame without read-back or glFinish (the caller brackets it; benchmarks).
    void draw_frame_for_timing() { draw_frame(); }
    // Milliseconds of `frames` beauty frames, each between glFinish calls (no read-back).
    std::vector<double> time_frames(int frames);

    // A cube face as captured (rgba, rows as stored by GL: row 0 is t = −1).
    std::vector<float> read_cube_face(int face) const;
    int cube_size() const { return scene_.environment.cube_size; }
    const EnvironmentCube* cube() const { return cube_; }

    // The program of `builder`, linked once (through the program cache) with this scene's environment and camera
    // uniforms set on first use; for the effects' own passes too.
    const BuiltProgram& program(const ShaderBuilder& builder);
    // The vertex array of every full-screen draw.
    GLuint vertex_array() const { return vao_.id(); }
    const Scene& scene() const { return scene_; }
    const Features& features() const { return features_; }
    // The environment's textures and what every effect binds for a program that reads the environment (the
    // capture, the background, the spheres; an effect's own capture of the room).
    void bind_environment(const BuiltProgram& program);
    // The spheres `which`, as seen from `view` on a width × height viewport, into the bound framebuffer with the
    // depth test on (each sphere writes its ray distance into alpha and t/(t+1) into depth): what an effect's
    // per-object map holds. The programs get the scene's camera back afterwards.
    void draw_spheres(const CameraBasis& view, int width, int height, std::span<const std::size_t> which);
    // Sphere i's Fresnel in the frames drawn now.
    const SphereFresnel& fresnel(std::size_t sphere) const { return *fresnel_.at(sphere); }
    // The programs linked so far, by their builder's key, for --explain and tests.
    std::vector<std::string> compiled_variants() const;

private:
    EnvironmentCube::Descriptor cube_descriptor() const;
    void set_camera_uniforms(GLuint program) const;
    void draw_frame(bool diagnostics = false);
    // A camera other than the scene's and its viewport (an effect's per-object map face).
    struct View {
        CameraBasis basis;
        int width = 0, height = 0;
    };
    // Sphere i's draw with its program, seen by the scene's camera or by `view` (whose uniforms it sets for the
    // draw and gives back to the scene's camera after it).
    void draw_sphere(std::size_t i, bool diagnostics, const View* view = nullptr);
    Image read_frame() const;

    const Scene& scene_;
    Features features_;
    std::vector<const SphereFresnel*> fresnel_;
    std::optional<ProgramCache> own_programs_;
    ProgramCache* program_cache_;
    std::map<std::string, BuiltProgram> programs_;  // by builder key, this scene's uniforms set
    gl::VertexArray vao_;
    std::optional<EnvironmentCube> own_cube_;
    std::optional<EquirectTexture> own_equirect_;
    const EnvironmentCube* cube_ = nullptr;
    const EquirectTexture* equirect_ = nullptr;
    Blackboard frame_;
    gl::Framebuffer framebuffer_;
    gl::Texture color_;
    gl::Renderbuffer depth_;
};

}  // namespace metalfit::glpreview
