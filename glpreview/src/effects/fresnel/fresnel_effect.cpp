#include "fresnel_effect.hpp"

#include <map>
#include <stdexcept>

#include "glpreview/gl/objects.hpp"
#include "glpreview/gl/uniforms.hpp"
#include "glpreview/render/frame_inputs.hpp"
#include "glpreview/render/gpu_renderer.hpp"
#include "glpreview/render/preview_passes.hpp"
#include "libfit/base/errors.hpp"
#include "libfit/base/text.hpp"
#include "libfit/io/catalog.hpp"
#include "libfit/io/layer_materials.hpp"
#include "render/embedded_shaders.hpp"

namespace metalfit::glpreview {
namespace {

// The reference curves uploaded so far, by Fresnel (the renderer's, on its blackboard).
struct ReferenceLuts {
    std::map<const SphereFresnel*, gl::Texture> textures;

    GLuint texture(const SphereFresnel& f) {
        if (auto it = textures.find(&f); it != textures.end()) return it->second.id();
        gl::Texture lut = gl::create_texture(GL_TEXTURE_1D);
        std::vector<float> texels;
        for (const RGB& v : f.lut) texels.insert(texels.end(), {float(v.r), float(v.g), float(v.b)});
        glTextureStorage1D(lut.id(), 1, GL_RGB32F, static_cast<GLsizei>(f.lut.size()));
        glTextureSubImage1D(lut.id(), 0, 0, static_cast<GLsizei>(f.lut.size()), GL_RGB, GL_FLOAT, texels.data());
        glTextureParameteri(lut.id(), GL_TEXTURE_MIN_FILTER, GL_LINEAR);
        glTextureParameteri(lut.id(), GL_TEXTURE_MAG_FILTER, GL_LINEAR);
        glTextureParameteri(lut.id(), GL_TEXTURE_WRAP_S, GL_CLAMP_TO_EDGE);
        check_gl("uploading a reference LUT");
        return textures.emplace(&f, std::move(lut)).first->second.id();
    }
};

class FresnelEffect final : public Effect {
public:
    std::string_view name() const override { return "fresnel"; }

    std::vector<const char*> sphere_keys() const override {
        return {"material", "source", "film", "coat", "fresnel", "params"};
    }

    void read_sphere(const SceneReader& r, Sphere& s, Scene& /*scene*/) const override {
        r.read("material", s.material);
        r.read("source", s.source);
        // The layers over the metal: an index, a film/coat of the database or a file beside the scene, with its
        // thickness, as the command line's --film and --coat (the reference curve and every fit are then the
        // stack's). Their tables are loaded with the sphere's Fresnel (FresnelLibrary, a file under the scene's path
        // policy): here the argument's form only.
        for (auto [key, out] : {std::pair{"film", &s.film}, std::pair{"coat", &s.coat}}) {
            r.read(key, *out);
            if (out->empty()) continue;
            try {
                parse_layer_argument(std::string("--") + key, *out);
            } catch (const UsageError& e) {
                r.fail(r.field(key), e.what());
            }
        }
        std::string fresnel = "reference", params = "fit";
        r.read("fresnel", fresnel);
        r.read("params", params);
        if (params != "fit" && params != "closed")
            r.fail(r.field("params"), "unknown value '" + scene_excerpt(params) + "' (known: fit, closed)");
        if (fresnel != "reference")  // "params" is checked on a reference sphere too, and means nothing there
            s.fresnel = ModelFresnel{fresnel, params == "closed" ? ParameterSource::closed : ParameterSource::fit};
    }

    void declare_sphere(const SphereShader& shader, ShaderBuilder& builder) const override {
        if (const auto* model = std::get_if<ModelFresnel>(&shader.sphere.fresnel)) {
            if (shader.fresnel && !shader.fresnel->model)
                throw std::logic_error("GpuRenderer: sphere shows model " + model->model +
                                       " but its Fresnel is the reference");
            builder.fresnel_model(model->model, shader.fresnel ? shader.fresnel->model : nullptr);
        } else {
            if (shader.fresnel && shader.fresnel->model)
                throw std::logic_error("GpuRenderer: sphere shows the reference but its Fresnel is model " +
                                       std::string(shader.fresnel->model->id()));
            builder.fresnel_reference();
        }
        builder.source(shader_text("fresnel.glsl"));
    }

    void add_frame_input_passes(PreviewGraph& g) const override {
        if (g.features.reference_lut)
            g.frame.read(*(g.handles.luts = add_reference_luts_pass(g.graph, g.scene, g.in, g.run)));
        else
            g.graph.skip("reference-luts", "no sphere uses fresnel 'reference'");
        if (g.features.model_fits)
            g.frame.read(*(g.handles.parameters = add_model_parameters_pass(g.graph, g.features, g.in, g.run)));
        else
            g.graph.skip("model-parameters", "no sphere uses a libfit model");
    }

    void bind_sphere(const SphereDraw& draw) const override {
        if (draw.fresnel.model)
            set_model_parameters(draw.program.id(), *draw.fresnel.model, draw.fresnel.parameters);
        else
            draw.program.bind("u_fresnel_lut", draw.renderer.frame().state<ReferenceLuts>().texture(draw.fresnel));
    }

    void forget_fresnel(GpuRenderer& renderer, const SphereFresnel& fresnel) const override {
        renderer.frame().state<ReferenceLuts>().textures.erase(&fresnel);
    }
};

}  // namespace

graph::Handle<FresnelSet> add_reference_luts_pass(graph::PassGraph& graph, const Scene& scene, const SceneInputs& in,
                                                  PreviewRun* run) {
    return graph
        .add_pass<graph::Out<FresnelSet>>(
            {"reference-luts",
             "some sphere shows the exact reference: R_c(μ) from libfit into 1D RGB textures (256 texels)",
             graph::Processor::cpu},
            [&](graph::Builder& b, graph::Out<FresnelSet>& d) {
                b.read(in.materials);
                d.out = b.produce<FresnelSet>("fresnel-luts");
            },
            [run, &scene](const graph::Out<FresnelSet>& d, graph::Resources& r) {
                FresnelSet& set = r.emplace(d.out);
                for (std::size_t i = 0; i < scene.spheres.size(); ++i)
                    set.spheres.push_back(run->fresnel[i]->model ? nullptr : run->fresnel[i]);
            })
        .out;
}

graph::Handle<FresnelSet> add_model_parameters_pass(graph::PassGraph& graph, const Features& f, const SceneInputs& in,
                                                    PreviewRun* run) {
    return graph
        .add_pass<graph::Out<FresnelSet>>(
            {"model-parameters",
             "models " + join({f.models.begin(), f.models.end()}) +
                 ": parameters from libfit (Ceres fit or closed form)",
             graph::Processor::cpu},
            [&](graph::Builder& b, graph::Out<FresnelSet>& d) {
                b.read(in.materials);
                d.out = b.produce<FresnelSet>("model-parameters");
            },
            [run](const graph::Out<FresnelSet>& d, graph::Resources& r) {
                FresnelSet& set = r.emplace(d.out);
                for (const SphereFresnel* fresnel : run->fresnel)
                    set.spheres.push_back(fresnel->model ? fresnel : nullptr);
            })
        .out;
}

const Effect& fresnel_effect() {
    static const FresnelEffect effect;
    return effect;
}

}  // namespace metalfit::glpreview
