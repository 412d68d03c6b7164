// The GL side of a preview: environment capture into a cube map, the beauty frame (background + one draw per
// sphere with its shader variant), timing, and a probe of the reflection lookup for tests and benchmarks.
// Needs a current GlContext.
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
#include "glpreview/render/dfg_table.hpp"
#include "glpreview/render/gpu_resources.hpp"
#include "glpreview/io/image.hpp"
#include "glpreview/render/plan.hpp"
#include "glpreview/scene/scene.hpp"
#include "glpreview/render/sphere_fresnel.hpp"

namespace metalfit::glpreview {

// One probed reflection: where the lookup went, and the cube texel (radiance, distance) found there.
struct ProbeResult {
    Vec3 lookup;                // not normalised
    std::array<float, 4> texel;  // rgb radiance, a distance (when the cube stores distance)
};

// The GLSL call of a libfit model on the uniforms u_param[k] (one vec3 per parameter, R, G, B), e.g.
// "metalfit_f82_tint(u_param[0], u_param[1], mu)".
std::string model_call(const Model& model);
// Sets u_param[k] of `program` to parameter k's values for R, G and B.
void set_model_parameters(GLuint program, const Model& model, const ModelParameters& params);

class GpuRenderer {
public:
    // fresnel[i] belongs to scene.spheres[i]; `equirect` is the loaded image for an equirect environment (or null,
    // when the pass graph binds its texture with use_equirect()).
    // The scene's environment, camera and image size are read when the renderer is made and when a shader variant
    // is first compiled (their uniforms are set once then); the spheres are read at every frame, so they may move
    // or change their reflection settings and Fresnel kind between frames.
    // `programs`: where its GL programs are linked and kept (the context's, shared with the other renderers made in
    // it); none: a cache of its own.
    GpuRenderer(const Scene& scene, const Features& features, std::vector<const SphereFresnel*> fresnel,
                const Image* equirect, ProgramCache* programs = nullptr);
    GpuRenderer(const GpuRenderer&) = delete;
    GpuRenderer& operator=(const GpuRenderer&) = delete;

    // Replaces sphere i's Fresnel (the scene's sphere must show the same Fresnel: the reference or that model).
    void set_fresnel(std::size_t sphere, const SphereFresnel* fresnel);

    // Ray-casts the environment into `cube` (once; spheres may move afterwards) and reflects it from then on.
    void capture_environment(const EnvironmentCube& cube);
    // The same into a cube map of the renderer's own (tests, benchmarks without a graph), prefiltered too when the
    // features ask for it.
    void capture_environment();
    // Reflects an already captured cube / an equirect texture owned by the caller (the pass graph).
    void use_environment(const EnvironmentCube& cube) { cube_ = &cube; }
    void use_equirect(const EquirectTexture& texture) { equirect_ = &texture; }
    // GGX-prefilters the captured `source` (made with mipmaps) into `target`, every face and level
    // (shaders/prefilter.frag), and reflects rough prefiltered spheres from it from then on.
    void prefilter(const EnvironmentCube& source, const PrefilteredCube& target);
    void use_prefiltered(const PrefilteredCube& cube) { prefiltered_ = &cube; }
    // Downsamples the captured `source` (with distances) into `target`'s M × M area lights per face
    // (shaders/downsample.frag); rough localized spheres of that M read it from then on.
    void downsample(const EnvironmentCube& source, const DownsampledCube& target);
    void use_downsampled(const DownsampledCube& cube) { downsampled_[cube.m] = &cube; }
    // Uploads the DFG tables of rough spheres (once per Fresnel). A rough sphere whose table was never handed over
    // gets one made here (tests and benchmarks without a graph).
    void use_dfg(const DfgSet& set);
    Image render();  // one beauty frame, read back
    // The localization diagnostics of the same frame (no background, 0 outside the spheres): per pixel r = the
    // distance impostor's refinement steps taken, g = |ρ − 1| at its lookup point, b = 1 on impostor spheres.
    Image render_localization();
    // One beauty frame without read-back or glFinish (the caller brackets it; benchmarks).
    void draw_frame_for_timing() { draw_frame(); }
    // Milliseconds of `frames` beauty frames, each between glFinish calls (no read-back).
    std::vector<double> time_frames(int frames);

    // Reflection lookups of a sphere's reflection settings for rays (x relative to the reference point, unit R),
    // computed by the shader code the spheres use. Needs the captured cube map.
    std::vector<ProbeResult> probe(const Sphere& settings, std::span<const std::array<Vec3, 2>> rays);
    // A cube face as captured (rgba, rows as stored by GL: row 0 is t = −1).
    std::vector<float> read_cube_face(int face) const;
    int cube_size() const { return scene_.environment.cube_size; }
    const EnvironmentCube* cube() const { return cube_; }

    // The shader variants compiled so far (a #define set each), for --explain and tests.
    std::vector<std::string> compiled_variants() const;

private:
    EnvironmentCube::Descriptor cube_descriptor() const;
    GLuint program(const std::string& kind, const std::vector<std::string>& defines, const std::string& fresnel_call = {});
    void set_environment_uniforms(GLuint program) const;
    void set_camera_uniforms(GLuint program) const;
    void draw_frame(bool diagnostics = false);
    Image read_frame() const;
    void upload_lut(const SphereFresnel* fresnel);
    void upload_dfg(const SphereFresnel* fresnel, const DfgTable& table);

    const Scene& scene_;
    Features features_;
    std::vector<const SphereFresnel*> fresnel_;
    std::optional<ProgramCache> own_programs_;
    ProgramCache* program_cache_;
    std::map<std::string, GLuint> programs_;  // shader variants (in program_cache_), this scene's uniforms set
    gl::VertexArray vao_;
    std::optional<EnvironmentCube> own_cube_;
    std::optional<EquirectTexture> own_equirect_;
    const EnvironmentCube* cube_ = nullptr;
    const EquirectTexture* equirect_ = nullptr;
    std::optional<PrefilteredCube> own_prefiltered_;
    const PrefilteredCube* prefiltered_ = nullptr;
    std::map<int, DownsampledCube> own_downsampled_;
    std::map<int, const DownsampledCube*> downsampled_;  // by M
    std::map<const SphereFresnel*, gl::Texture> dfg_;  // DFG tables of rough spheres, by Fresnel
    std::map<const SphereFresnel*, gl::Texture> luts_;  // reference LUTs, uploaded on first use
    gl::Framebuffer framebuffer_;
    gl::Texture color_;
    gl::Renderbuffer depth_;
};

}  // namespace metalfit::glpreview
