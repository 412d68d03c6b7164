// The shader-cost benchmark as passes: compile one full-screen program per libfit model (and the reference LUT),
// time them interleaved into a colour target the graph creates, and keep the record.
#include <functional>
#include <string>
#include <vector>

#include "embedded_shaders.hpp"
#include "frame_timing.hpp"
#include "glpreview/gl/objects.hpp"
#include "glpreview/gl/uniforms.hpp"
#include "glpreview/render/gpu_renderer.hpp"
#include "gpu_bench_passes.hpp"
#include "libfit/models/model.hpp"

namespace metalfit::glpreview {
namespace {

using graph::Builder;
using graph::Handle;
using graph::PassGraph;
using graph::Processor;
using graph::Resources;
using Json = nlohmann::ordered_json;

// The square RGBA16F target every model-cost pass draws into.
struct CostTarget {
    struct Descriptor {
        int size = kShaderBenchSize;
    };
    static CostTarget create(const Descriptor& d) {
        CostTarget target{gl::create_framebuffer(), gl::create_texture(GL_TEXTURE_2D), d.size};
        glTextureStorage2D(target.color.id(), 1, GL_RGBA16F, d.size, d.size);
        glNamedFramebufferTexture(target.framebuffer.id(), GL_COLOR_ATTACHMENT0, target.color.id(), 0);
        return target;
    }
    gl::Framebuffer framebuffer;
    gl::Texture color;
    int size = 0;
};

// A 256-entry RGB curve in a linearly filtered 1D texture, as the preview's reference spheres use.
struct SyntheticReferenceLut {
    struct Descriptor {};
    static SyntheticReferenceLut create(const Descriptor&) {
        SyntheticReferenceLut lut{gl::create_texture(GL_TEXTURE_1D)};
        std::vector<float> texels;
        for (int i = 0; i < kReferenceLutSize; ++i) {
            const float mu = i / float(kReferenceLutSize - 1);
            texels.insert(texels.end(), {1 - 0.3f * mu, 1 - 0.5f * mu, 1 - 0.7f * mu});
        }
        glTextureStorage1D(lut.texture.id(), 1, GL_RGB32F, kReferenceLutSize);
        glTextureSubImage1D(lut.texture.id(), 0, 0, kReferenceLutSize, GL_RGB, GL_FLOAT, texels.data());
        glTextureParameteri(lut.texture.id(), GL_TEXTURE_MIN_FILTER, GL_LINEAR);
        glTextureParameteri(lut.texture.id(), GL_TEXTURE_MAG_FILTER, GL_LINEAR);
        return lut;
    }
    gl::Texture texture;
};

struct CostProgram {
    std::string name;  // a model id or "reference-lut"
    gl::Program program;
    BuiltProgram built;  // its id and sampler units
};
using CostPrograms = std::vector<CostProgram>;

struct ShaderRounds {
    std::vector<std::string> names;
    RoundTimes ms;
    FrameTimer timer = FrameTimer::wall;
};

// One model's program (model null: the reference LUT's), assembled like the spheres' Fresnel (ShaderBuilder).
CostProgram cost_program(const Model* model) {
    const std::string name = model ? std::string(model->id()) : "reference-lut";
    ShaderBuilder builder("model-cost");
    builder.define("EVALUATIONS", std::to_string(kShaderBenchEvaluationsPerPixel));
    if (model)
        builder.fresnel_model(model->id(), model);
    else
        builder.define("FRESNEL_PARAMETERS", "1").define("FRESNEL_CALL", "reference_lut(mu)");
    builder.sampler("u_fresnel_lut").source(shader_text("model_cost.frag"));
    gl::Program program(
        link_program({fullscreen_vertex_stage(), {GL_FRAGMENT_SHADER, builder.text()}}, "model-cost " + name));
    if (model) {  // neutral parameter values, the same in R, G and B: the cost does not depend on them
        const ChannelParameters p = model->neutral_starts().front();
        set_model_parameters(program.id(), *model, {p, p, p});
    }
    const float size = float(kShaderBenchSize);
    glProgramUniform2f(program.id(), glGetUniformLocation(program.id(), "u_viewport"), size, size);
    BuiltProgram built(program.id(), builder.samplers());
    glProgramUniform1i(program.id(), glGetUniformLocation(program.id(), "u_fresnel_lut"), built.unit("u_fresnel_lut"));
    return {name, std::move(program), built};
}

Json shader_record(const GpuBenchRun& run, int rounds, const ShaderRounds& timed) {
    std::size_t exact = 0;
    for (std::size_t i = 0; i < timed.names.size(); ++i)
        if (timed.names[i] == "conductor-rgb") exact = i;
    Json j;
    j["renderer"] = run.context->renderer();
    j["size"] = {kShaderBenchSize, kShaderBenchSize};
    j["frames"] = rounds;
    j["evaluations_per_pixel"] = kShaderBenchEvaluationsPerPixel;
    j["clock"] = frame_timer_name(timed.timer);
    j["models"] = Json::array();
    for (std::size_t i = 0; i < timed.names.size(); ++i) {
        std::vector<double> per_round;
        for (std::size_t k = 0; k < timed.ms[i].size() && k < timed.ms[exact].size(); ++k)
            per_round.push_back(timed.ms[i][k] / timed.ms[exact][k]);
        const Ratio ratio = paired_ratio(timed.ms[i], timed.ms[exact]);
        j["models"].push_back({{"model", timed.names[i]},
                               {"ms_per_frame", median(timed.ms[i])},
                               {"ratio_to_conductor_rgb", ratio.median},
                               {"ratio_noise", ratio.noise},
                               {"ratio_quartiles", {quantile(per_round, 0.25), quantile(per_round, 0.75)}}});
    }
    return j;
}

}  // namespace

Handle<Json> add_shader_cost_passes(PassGraph& graph, GpuBenchRun& run) {
    const int rounds = run.quick ? 5 : 15;
    struct Programs {
        Handle<CostPrograms> out;
    };
    const Handle<CostPrograms> programs =
        graph
            .add_pass<Programs>(
                {"model-cost-programs",
                 "one full-screen program per libfit model (its GLSL, " +
                     std::to_string(kShaderBenchEvaluationsPerPixel) +
                     " evaluations per pixel) and one reading the reference LUT",
                 Processor::gpu},
                [](Builder& b, Programs& d) { d.out = b.produce<CostPrograms>("model-cost-programs"); },
                [](const Programs& d, Resources& r) {
                    CostPrograms& all = r.emplace(d.out);
                    for (const Model* model : all_models()) all.push_back(cost_program(model));
                    all.push_back(cost_program(nullptr));
                })
            .out;
    struct Timing {
        Handle<CostPrograms> programs;
        Handle<CostTarget> target;
        Handle<SyntheticReferenceLut> lut;
        Handle<ShaderRounds> out;
    };
    const Handle<ShaderRounds> timed =
        graph
            .add_pass<Timing>(
                {"shader-timing",
                 std::to_string(rounds) + " interleaved rounds of one " + std::to_string(kShaderBenchSize) +
                     "² frame per program, each between glFinish calls",
                 Processor::gpu},
                [&](Builder& b, Timing& d) {
                    d.programs = b.read(programs);
                    d.target = b.create<CostTarget>("cost-target", {kShaderBenchSize});
                    d.lut = b.create<SyntheticReferenceLut>("synthetic-reference-lut", {});
                    d.out = b.produce<ShaderRounds>("shader-rounds");
                },
                [rounds](const Timing& d, Resources& r) {
                    const CostTarget& target = r.get(d.target);
                    const GLuint lut = r.get(d.lut).texture.id();
                    const gl::VertexArray vao = gl::create_vertex_array();
                    ShaderRounds& timed = r.emplace(d.out);
                    std::vector<std::function<void()>> variants;
                    for (const CostProgram& p : r.get(d.programs)) {
                        timed.names.push_back(p.name);
                        variants.push_back([&target, lut, &vao, &p] {
                            glBindFramebuffer(GL_FRAMEBUFFER, target.framebuffer.id());
                            glViewport(0, 0, target.size, target.size);
                            glBindVertexArray(vao.id());
                            p.built.bind("u_fresnel_lut", lut);
                            glUseProgram(p.program.id());
                            glDrawArrays(GL_TRIANGLES, 0, 3);
                        });
                    }
                    timed.timer = frame_timer();
                    timed.ms = interleaved_rounds(variants, rounds);
                    check_gl("shader benchmark");
                    glBindFramebuffer(GL_FRAMEBUFFER, 0);
                })
            .out;
    struct Record {
        Handle<Json> out;
    };
    return graph
        .add_pass<Record>(
            {"shader-record", "per program: median ms per frame and the paired ratio to conductor-rgb", Processor::cpu},
            [&](Builder& b, Record& d) {
                b.read(timed);
                d.out = b.produce<Json>("shader-bench");
            },
            [&run, rounds, timed](const Record& d, Resources& r) {
                r.emplace(d.out, shader_record(run, rounds, r.get(timed)));
            })
        .out;
}

}  // namespace metalfit::glpreview
