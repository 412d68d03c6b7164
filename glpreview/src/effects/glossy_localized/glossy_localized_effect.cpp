#include "glossy_localized_effect.hpp"

#include <map>

#include "glpreview/gl/uniforms.hpp"
#include "glpreview/render/frame_inputs.hpp"
#include "glpreview/render/gpu_renderer.hpp"
#include "glpreview/render/preview_passes.hpp"
#include "libfit/base/text.hpp"
#include "render/embedded_shaders.hpp"

namespace metalfit::glpreview {
namespace {

using graph::Builder;
using graph::Handle;
using graph::PassGraph;
using graph::Processor;
using graph::Resources;

bool applies(const Sphere& sphere) { return sphere.rough() && sphere.glossy == GlossyMethod::localized; }

// The downsampled cubes the renderer made itself (derive_from_environment), by M.
struct OwnDownsampledCubes {
    std::map<int, DownsampledCube> cubes;
};

class GlossyLocalizedEffect final : public Effect {
public:
    std::string_view name() const override { return "glossy-localized"; }

    std::vector<const char*> sphere_keys() const override { return {"localized_size"}; }

    void read_sphere(const SceneReader& r, Sphere& s, Scene& scene) const override {
        r.read("localized_size", s.localized_size, 2, 16);
        if (r.has("reflection") && applies(s))
            scene.warnings.push_back(r.file().string() + ": " + r.field("reflection") +
                                     ": ignored: glossy 'localized' localizes by the area lights' positions");
        if (r.has("localized_size") && !applies(s))
            scene.warnings.push_back(r.file().string() + ": " + r.field("localized_size") +
                                     ": ignored: only a rough sphere with glossy 'localized' uses it");
    }

    void declare_sphere(const SphereShader& shader, ShaderBuilder& builder) const override {
        const Sphere& sphere = shader.sphere;
        if (!applies(sphere)) return;
        builder.define("GLOSSY_LOCALIZED")
            .define("LOCALIZED_SUBDIVISIONS",
                    std::to_string(localized_subdivisions(sphere.roughness, sphere.localized_size)))
            .source(shader_text("cube_face.glsl"))
            .source(shader_text("ggx.glsl"))
            .source(shader_text("glossy_localized.glsl"))
            .sampler("u_area_radiance")
            .sampler("u_area_position")
            .radiance("localized_glossy(p - u_reference, N, -d, mu)");
    }

    void bind_sphere(const SphereDraw& draw) const override {
        if (!applies(draw.sphere)) return;
        const DownsampledCube& cube = draw.renderer.frame().get<DownsampledCube>(
            "the downsampled cube of M = " + std::to_string(draw.sphere.localized_size) +
                " (a localized sphere needs it)",
            std::to_string(draw.sphere.localized_size));
        set_uniform(draw.program.id(), "u_roughness", static_cast<float>(draw.sphere.roughness));
        draw.program.bind("u_area_radiance", cube.radiance.id());
        draw.program.bind("u_area_position", cube.position.id());
    }

    void add_frame_input_passes(PreviewGraph& g) const override {
        if (!g.features.downsample_sizes.empty() && g.handles.environment.cube) {
            for (int m : g.features.downsample_sizes)
                g.frame.add(add_downsample_environment_pass(g.graph, g.scene, m, *g.handles.environment.cube, g.run),
                            std::to_string(m));
        } else {
            g.graph.skip("downsample-environment", "no sphere is rough with glossy 'localized'");
        }
    }

    void derive_from_environment(GpuRenderer& renderer, const EnvironmentCube& cube) const override {
        auto& own = renderer.frame().state<OwnDownsampledCubes>().cubes;
        for (int m : renderer.features().downsample_sizes) {
            auto it = own.find(m);
            if (it == own.end()) it = own.emplace(m, DownsampledCube::create({m})).first;
            downsample_environment(renderer, cube, it->second);
        }
    }
};

}  // namespace

const Effect& glossy_localized_effect() {
    static const GlossyLocalizedEffect effect;
    return effect;
}

void downsample_environment(GpuRenderer& renderer, const EnvironmentCube& source, const DownsampledCube& target) {
    ShaderBuilder downsample("downsample");
    downsample.source(shader_text("environment.glsl"))
        .source(shader_text("cube_face.glsl"))
        .source(shader_text("downsample.frag"))
        .sampler("u_env");
    const BuiltProgram& p = renderer.program(downsample);
    set_uniform(p.id(), "u_source_size", source.size);
    set_uniform(p.id(), "u_m", target.m);
    const gl::Framebuffer fbo = gl::create_framebuffer();
    glNamedFramebufferTexture(fbo.id(), GL_COLOR_ATTACHMENT0, target.radiance.id(), 0);
    glNamedFramebufferTexture(fbo.id(), GL_COLOR_ATTACHMENT1, target.position.id(), 0);
    const GLenum buffers[2] = {GL_COLOR_ATTACHMENT0, GL_COLOR_ATTACHMENT1};
    glNamedFramebufferDrawBuffers(fbo.id(), 2, buffers);
    if (glCheckNamedFramebufferStatus(fbo.id(), GL_FRAMEBUFFER) != GL_FRAMEBUFFER_COMPLETE)
        throw GlError("the downsampled cube cannot be rendered to");
    glBindFramebuffer(GL_FRAMEBUFFER, fbo.id());
    glUseProgram(p.id());
    glBindVertexArray(renderer.vertex_array());
    glDisable(GL_DEPTH_TEST);
    p.bind("u_env", source.texture.id());
    glViewport(0, 0, 6 * target.m, target.m);
    glDrawArrays(GL_TRIANGLES, 0, 3);
    glBindFramebuffer(GL_FRAMEBUFFER, 0);
    check_gl("downsampling the environment");
    renderer.frame().put(target, std::to_string(target.m));
}

Handle<DownsampledCube> add_downsample_environment_pass(PassGraph& graph, const Scene& scene, int m,
                                                        Handle<EnvironmentCube> cube, PreviewRun* run) {
    struct Data {
        Handle<EnvironmentCube> in;
        Handle<DownsampledCube> out;
    };
    std::vector<std::string> spheres;
    for (std::size_t i = 0; i < scene.spheres.size(); ++i)
        if (applies(scene.spheres[i]) && scene.spheres[i].localized_size == m) spheres.push_back(std::to_string(i));
    const std::string size = std::to_string(m);
    return graph
        .add_pass<Data>(
            {"downsample-environment " + size,
             "sphere(s) " + join(spheres) + " rough with glossy 'localized': the cube as " + size + " × " + size +
                 " area lights per face (average radiance and position, thesis ch. 5)",
             Processor::gpu},
            [&](Builder& b, Data& d) {
                d.in = b.read(cube);
                d.out = b.create<DownsampledCube>("downsampled-cube " + size, {m});
            },
            [run](const Data& d, Resources& r) { downsample_environment(run->renderer(), r.get(d.in), r.get(d.out)); })
        .out;
}

}  // namespace metalfit::glpreview
