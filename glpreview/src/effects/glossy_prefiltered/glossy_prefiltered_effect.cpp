#include "glossy_prefiltered_effect.hpp"

#include <map>
#include <stdexcept>

#include "glpreview/gl/uniforms.hpp"
#include "glpreview/render/dfg_table.hpp"
#include "glpreview/render/frame_inputs.hpp"
#include "glpreview/render/gpu_renderer.hpp"
#include "glpreview/render/preview_passes.hpp"
#include "glpreview/scene/glossy_choice.hpp"
#include "libfit/base/text.hpp"
#include "render/embedded_shaders.hpp"

namespace metalfit::glpreview {
namespace {

using graph::Builder;
using graph::Handle;
using graph::Out;
using graph::PassGraph;
using graph::Processor;
using graph::Resources;

bool applies(const Sphere& sphere) { return sphere.rough() && sphere.glossy == GlossyMethod::prefiltered; }

// The DFG tables uploaded so far, by Fresnel (the renderer's, on its blackboard): from the graph's DfgSet of the
// sphere's Fresnel where one was handed over, else made here on first use (tests, the sheet, benchmarks).
struct DfgTextures {
    std::map<const SphereFresnel*, gl::Texture> textures;

    GLuint texture(const SphereFresnel& fresnel, const DfgSet* made) {
        if (auto it = textures.find(&fresnel); it != textures.end()) return it->second.id();
        const DfgTable* given = nullptr;
        if (made)
            if (const auto it = made->tables.find(&fresnel); it != made->tables.end()) given = &it->second;
        const DfgTable table = given ? *given : make_dfg_table(fresnel);
        gl::Texture texture = gl::create_texture(GL_TEXTURE_2D);
        std::vector<float> texels;
        for (const RGB& v : table.values) texels.insert(texels.end(), {float(v.r), float(v.g), float(v.b)});
        glTextureStorage2D(texture.id(), 1, GL_RGB32F, DfgTable::kMuSize, DfgTable::kRoughnessSize);
        glTextureSubImage2D(texture.id(), 0, 0, 0, DfgTable::kMuSize, DfgTable::kRoughnessSize, GL_RGB, GL_FLOAT,
                            texels.data());
        glTextureParameteri(texture.id(), GL_TEXTURE_MIN_FILTER, GL_LINEAR);
        glTextureParameteri(texture.id(), GL_TEXTURE_MAG_FILTER, GL_LINEAR);
        glTextureParameteri(texture.id(), GL_TEXTURE_WRAP_S, GL_CLAMP_TO_EDGE);
        glTextureParameteri(texture.id(), GL_TEXTURE_WRAP_T, GL_CLAMP_TO_EDGE);
        check_gl("uploading a DFG table");
        return textures.emplace(&fresnel, std::move(texture)).first->second.id();
    }
};

// The prefiltered cube the renderer made itself (derive_from_environment).
struct OwnPrefilteredCube {
    std::optional<PrefilteredCube> cube;
};

Handle<DfgSet> add_dfg_table_pass(PassGraph& graph, const Scene& scene, const std::string& fresnel,
                                  const SceneInputs& in, PreviewRun* run) {
    std::vector<std::size_t> spheres;
    for (std::size_t i = 0; i < scene.spheres.size(); ++i)
        if (applies(scene.spheres[i]) && fresnel_name(scene.spheres[i].fresnel) == fresnel) spheres.push_back(i);
    std::vector<std::string> names;
    for (std::size_t i : spheres) names.push_back(std::to_string(i));
    return graph
        .add_pass<Out<DfgSet>>(
            {"dfg-table " + fresnel,
             "rough sphere(s) " + join(names) + " use " + fresnel +
                 ": the GGX-weighted integral of its own F over (μ, roughness), " + std::to_string(DfgTable::kMuSize) +
                 " × " + std::to_string(DfgTable::kRoughnessSize) + " per material",
             Processor::cpu},
            [&](Builder& b, Out<DfgSet>& d) {
                b.read(in.materials);
                d.out = b.produce<DfgSet>("dfg-tables " + fresnel);
            },
            [run, spheres](const Out<DfgSet>& d, Resources& r) {
                DfgSet& set = r.emplace(d.out);
                for (std::size_t i : spheres)
                    if (!set.tables.count(run->fresnel[i]))
                        set.tables.emplace(run->fresnel[i], make_dfg_table(*run->fresnel[i]));
            })
        .out;
}

class GlossyPrefilteredEffect final : public Effect {
public:
    std::string_view name() const override { return "glossy-prefiltered"; }

    std::vector<const char*> sphere_keys() const override { return {"roughness", "glossy"}; }

    void read_sphere(const SceneReader& r, Sphere& s, Scene& scene) const override {
        r.read("roughness", s.roughness, 0, 1);
        r.read_enum("glossy", s.glossy_request, kGlossyRequestNames);
        const GlossyChoice choice = choose_glossy_method(s.roughness, s.glossy_request);
        s.glossy = choice.method;
        if (choice.fell_back && s.rough())
            scene.warnings.push_back(r.file().string() + ": " + r.field("glossy") + ": " + choice.reason);
        if (s.rough() && !scene.environment.captured())
            r.fail(
                r.field("roughness"),
                "rough spheres need a captured environment (room, sphere-room or an equirect with a proxy): an equirect at infinity is not prefiltered");
        if (r.has("glossy") && !s.rough())
            scene.warnings.push_back(r.file().string() + ": " + r.field("glossy") +
                                     ": ignored: the sphere is a mirror (roughness 0)");
    }

    void declare_sphere(const SphereShader& shader, ShaderBuilder& builder) const override {
        if (!applies(shader.sphere)) return;
        builder.define("GLOSSY_PREFILTERED")
            .source(shader_text("glossy_prefiltered.glsl"))
            .sampler("u_prefiltered")
            .sampler("u_dfg")
            .radiance("prefiltered_glossy(p, R, mu)");
    }

    void bind_sphere(const SphereDraw& draw) const override {
        if (!applies(draw.sphere)) return;
        Blackboard& frame = draw.renderer.frame();
        const PrefilteredCube& cube = frame.get<PrefilteredCube>("the prefiltered cube (a rough sphere needs it)");
        const GLuint p = draw.program.id();
        set_uniform(p, "u_roughness", static_cast<float>(draw.sphere.roughness));
        set_uniform(p, "u_prefiltered_levels", static_cast<float>(cube.levels));
        draw.program.bind("u_prefiltered", cube.texture.id());
        draw.program.bind("u_dfg", frame.state<DfgTextures>().texture(
                                       draw.fresnel, frame.find<DfgSet>(fresnel_name(draw.sphere.fresnel))));
    }

    void add_frame_input_passes(PreviewGraph& g) const override {
        if (g.features.prefiltered_map && g.handles.environment.cube) {
            g.frame.add(add_prefilter_environment_pass(g.graph, g.scene, *g.handles.environment.cube, g.run));
            for (const std::string& fresnel : g.features.dfg_models)
                g.frame.add(add_dfg_table_pass(g.graph, g.scene, fresnel, g.in, g.run), fresnel);
        } else {
            g.graph.skip("prefilter-environment",
                         "no sphere is rough with glossy 'prefiltered' (mirrors: roughness 0)");
            g.graph.skip("dfg-table", "no sphere is rough with glossy 'prefiltered'");
        }
    }

    void derive_from_environment(GpuRenderer& renderer, const EnvironmentCube& cube) const override {
        if (!renderer.features().prefiltered_map) return;
        auto& own = renderer.frame().state<OwnPrefilteredCube>();
        const int size = PrefilteredCube::size_for(renderer.scene().environment.cube_size);
        if (!own.cube) own.cube = PrefilteredCube::create({size, PrefilteredCube::levels_for(size)});
        prefilter_environment(renderer, cube, *own.cube);
    }

    void forget_fresnel(GpuRenderer& renderer, const SphereFresnel& fresnel) const override {
        renderer.frame().state<DfgTextures>().textures.erase(&fresnel);
    }
};

}  // namespace

const Effect& glossy_prefiltered_effect() {
    static const GlossyPrefilteredEffect effect;
    return effect;
}

void prefilter_environment(GpuRenderer& renderer, const EnvironmentCube& source, const PrefilteredCube& target) {
    ShaderBuilder prefilter("prefilter");
    prefilter.source(shader_text("environment.glsl"))
        .source(shader_text("cube_face.glsl"))
        .source(shader_text("prefilter.frag"))
        .sampler("u_env");
    const BuiltProgram& p = renderer.program(prefilter);
    set_uniform(p.id(), "u_source_size", source.size);
    set_uniform(p.id(), "u_samples", 64);
    const gl::Framebuffer fbo = gl::create_framebuffer();
    glUseProgram(p.id());
    glBindVertexArray(renderer.vertex_array());
    glDisable(GL_DEPTH_TEST);
    p.bind("u_env", source.texture.id());
    for (int level = 0; level < target.levels; ++level) {
        const int n = std::max(1, target.size >> level);
        set_uniform(p.id(), "u_size", n);
        set_uniform(p.id(), "u_roughness", target.levels > 1 ? float(level) / float(target.levels - 1) : 0.0f);
        glViewport(0, 0, n, n);
        for (int face = 0; face < 6; ++face) {
            glNamedFramebufferTextureLayer(fbo.id(), GL_COLOR_ATTACHMENT0, target.texture.id(), level, face);
            if (glCheckNamedFramebufferStatus(fbo.id(), GL_FRAMEBUFFER) != GL_FRAMEBUFFER_COMPLETE)
                throw GlError("prefiltered cube face " + std::to_string(face) + " level " + std::to_string(level) +
                              " cannot be rendered to");
            glBindFramebuffer(GL_FRAMEBUFFER, fbo.id());
            set_uniform(p.id(), "u_face", face);
            glDrawArrays(GL_TRIANGLES, 0, 3);
        }
    }
    glBindFramebuffer(GL_FRAMEBUFFER, 0);
    check_gl("prefiltering the environment");
    renderer.frame().put(target);
}

Handle<PrefilteredCube> add_prefilter_environment_pass(PassGraph& graph, const Scene& scene,
                                                       Handle<EnvironmentCube> cube, PreviewRun* run) {
    struct Data {
        Handle<EnvironmentCube> in;
        Handle<PrefilteredCube> out;
    };
    const int size = PrefilteredCube::size_for(scene.environment.cube_size), levels = PrefilteredCube::levels_for(size);
    std::vector<std::string> rough;
    for (std::size_t i = 0; i < scene.spheres.size(); ++i)
        if (applies(scene.spheres[i])) rough.push_back(std::to_string(i));
    return graph
        .add_pass<Data>(
            {"prefilter-environment",
             "sphere(s) " + join(rough) + " rough with glossy 'prefiltered': GGX-prefiltered " + std::to_string(size) +
                 "² cube, " + std::to_string(levels) + " mip levels (one per roughness step of 1/" +
                 std::to_string(levels - 1) + "), filtered importance sampling",
             Processor::gpu},
            [&](Builder& b, Data& d) {
                d.in = b.read(cube);
                d.out = b.create<PrefilteredCube>("prefiltered-cube", {size, levels});
            },
            [run](const Data& d, Resources& r) { prefilter_environment(run->renderer(), r.get(d.in), r.get(d.out)); })
        .out;
}

}  // namespace metalfit::glpreview
