#include "glpreview/render/gpu_bench.hpp"

#include <functional>

#include "embedded_shaders.hpp"
#include "frame_timing.hpp"
#include "glpreview/render/environment.hpp"
#include "glpreview/render/gpu_renderer.hpp"
#include "glpreview/render/sphere_fresnel.hpp"
#include "glpreview/render/sphere_metrics.hpp"
#include "libfit/models/model.hpp"

namespace metalfit::glpreview {
namespace {

// Runs `rounds` rounds; each round times one call of every variant in turn (between glFinish calls). Returns the
// milliseconds of every round per variant: medians and ratios are libfit's (median, paired_ratio), as on the CPU.
template <typename Variant>
std::vector<std::vector<double>> interleaved_rounds(const std::vector<Variant>& variants, int rounds) {
    std::vector<std::vector<double>> ms(variants.size());
    for (const auto& v : variants) v();  // warm-up: compile, first-use costs
    glFinish();
    for (int round = 0; round < rounds; ++round)
        for (std::size_t i = 0; i < variants.size(); ++i) ms[i].push_back(finished_ms(variants[i]));
    return ms;
}

}  // namespace

nlohmann::ordered_json bench_shaders(GlContext& context, bool quick) {
    const int size = 1024, rounds = quick ? 5 : 15;
    const gl::Framebuffer framebuffer = gl::create_framebuffer();
    const gl::Texture color = gl::create_texture(GL_TEXTURE_2D);
    glTextureStorage2D(color.id(), 1, GL_RGBA16F, size, size);
    glNamedFramebufferTexture(framebuffer.id(), GL_COLOR_ATTACHMENT0, color.id(), 0);
    const gl::VertexArray vao = gl::create_vertex_array();
    const gl::Texture lut = gl::create_texture(GL_TEXTURE_1D);  // a 256-entry RGB curve, as the preview's reference spheres use
    std::vector<float> texels;
    for (int i = 0; i < kReferenceLutSize; ++i) {
        const float mu = i / float(kReferenceLutSize - 1);
        texels.insert(texels.end(), {1 - 0.3f * mu, 1 - 0.5f * mu, 1 - 0.7f * mu});
    }
    glTextureStorage1D(lut.id(), 1, GL_RGB32F, kReferenceLutSize);
    glTextureSubImage1D(lut.id(), 0, 0, kReferenceLutSize, GL_RGB, GL_FLOAT, texels.data());
    glTextureParameteri(lut.id(), GL_TEXTURE_MIN_FILTER, GL_LINEAR);
    glTextureParameteri(lut.id(), GL_TEXTURE_MAG_FILTER, GL_LINEAR);

    struct Entry {
        std::string name;
        gl::Program program;
    };
    std::vector<Entry> entries;
    auto add = [&](const std::string& name, const std::string& library, const std::string& call, const Model* model) {
        const std::string fragment = "#version 450 core\n#define EVALUATIONS " + std::to_string(kShaderBenchEvaluationsPerPixel) +
                                     "\n#define FRESNEL_CALL " + call + "\n" + library + std::string(shader_text("model_cost.frag"));
        gl::Program program(link_program({fullscreen_vertex_stage(), {GL_FRAGMENT_SHADER, fragment}}, "model-cost " + name));
        if (model) {  // neutral parameter values, the same in R, G and B: the cost does not depend on them
            const ChannelParameters p = model->neutral_starts().front();
            set_model_parameters(program.id(), *model, {p, p, p});
        }
        glProgramUniform2f(program.id(), glGetUniformLocation(program.id(), "u_viewport"), float(size), float(size));
        glProgramUniform1i(program.id(), glGetUniformLocation(program.id(), "u_fresnel_lut"), 0);
        entries.push_back({name, std::move(program)});
    };
    for (const Model* model : all_models()) add(std::string(model->id()), model->glsl_source(), model_call(*model), model);
    add("reference-lut", "", "reference_lut(mu)", nullptr);

    std::vector<std::function<void()>> variants;
    for (const Entry& e : entries)
        variants.push_back([&, id = e.program.id()] {
            glBindFramebuffer(GL_FRAMEBUFFER, framebuffer.id());
            glViewport(0, 0, size, size);
            glBindVertexArray(vao.id());
            glBindTextureUnit(0, lut.id());
            glUseProgram(id);
            glDrawArrays(GL_TRIANGLES, 0, 3);
        });
    const std::vector<std::vector<double>> ms = interleaved_rounds(variants, rounds);
    check_gl("shader benchmark");
    std::size_t exact = 0;
    for (std::size_t i = 0; i < entries.size(); ++i)
        if (entries[i].name == "conductor-rgb") exact = i;
    nlohmann::ordered_json j;
    j["renderer"] = context.renderer();
    j["size"] = {size, size};
    j["frames"] = rounds;
    j["evaluations_per_pixel"] = kShaderBenchEvaluationsPerPixel;
    j["models"] = nlohmann::ordered_json::array();
    for (std::size_t i = 0; i < entries.size(); ++i)
        j["models"].push_back({{"model", entries[i].name}, {"ms_per_frame", median(ms[i])},
                                {"ratio_to_conductor_rgb", paired_ratio(ms[i], ms[exact]).median}});
    glBindFramebuffer(GL_FRAMEBUFFER, 0);
    return j;
}

nlohmann::ordered_json bench_localization(GlContext& context, const PreviewOptions& options, bool quick) {
    Scene difficult = load_scene(options.data_dir / "scenes" / "sheet.json");
    difficult.width = quick ? 256 : 512;
    difficult.height = quick ? 256 : 512;
    // The camera close to the sphere, so that the reflection (not the background) fills most of the frame.
    const Sphere& subject = difficult.spheres.at(0);
    difficult.camera.look_at = subject.center;
    difficult.camera.position = subject.center + Vec3{0, 0.15, 0.95};
    difficult.camera.fov_y_deg = 70;
    Scene empty = difficult;
    empty.environment.room.boxes.clear();
    const int rounds = quick ? 3 : 7;

    struct Row {
        ReflectionMode mode;
        Strategy strategy;
        int iterations;
    };
    std::vector<Row> rows{{ReflectionMode::classic, Strategy::secant, 0}, {ReflectionMode::box_parallax, Strategy::secant, 0}};
    for (Strategy s : {Strategy::secant, Strategy::false_position, Strategy::mixed})
        for (int n : {0, 1, 2, 4, 8, 16}) rows.push_back({ReflectionMode::distance_impostor, s, n});

    nlohmann::ordered_json j;
    j["renderer"] = context.renderer();
    j["size"] = {difficult.width, difficult.height};
    j["frames"] = rounds;
    j["rooms"] = nlohmann::ordered_json::array();
    FresnelLibrary library(options.data_dir, options.ocio, difficult.file);
    for (auto [name, scene] : {std::pair<const char*, Scene*>{"empty", &empty}, {"difficult", &difficult}}) {
        Sphere& sphere = scene->spheres.at(0);
        sphere.fresnel = "reference";
        sphere.reflection = ReflectionMode::distance_impostor;  // the renderer's cube stores distances
        const SphereFresnel* fresnel = &library.get(sphere, "spheres[0]");
        const EnvironmentTracer tracer(scene->environment);
        const ReferenceRender reference = render_reference(*scene, {fresnel}, tracer, options.threads);
        GpuRenderer gpu(*scene, plan_features(*scene), {fresnel}, nullptr);
        gpu.capture_environment();

        auto apply = [&](const Row& row) {
            sphere.reflection = row.mode;
            sphere.strategy = row.strategy;
            sphere.iterations = row.iterations;
        };
        std::vector<std::function<void()>> variants;
        nlohmann::ordered_json out_rows = nlohmann::ordered_json::array();
        std::vector<SphereError> errors;
        for (const Row& row : rows) {
            apply(row);
            errors.push_back(sphere_errors(gpu.render(), reference, 1).front());
            variants.push_back([&, row] {
                apply(row);
                gpu.draw_frame_for_timing();
            });
        }
        const std::vector<std::vector<double>> ms = interleaved_rounds(variants, rounds);
        for (std::size_t i = 0; i < rows.size(); ++i) {
            const bool impostor = rows[i].mode == ReflectionMode::distance_impostor;
            out_rows.push_back({{"mode", to_string(rows[i].mode)},
                                {"strategy", impostor ? nlohmann::ordered_json(to_string(rows[i].strategy)) : nlohmann::ordered_json()},
                                {"iterations", impostor ? rows[i].iterations : 0},
                                {"ms_per_frame", median(ms[i])},
                                {"ratio_to_classic", paired_ratio(ms[i], ms[0]).median},
                                {"rmse", errors[i].rmse},
                                {"mean_abs", errors[i].mean_abs}});
        }
        j["rooms"].push_back({{"room", name}, {"rows", out_rows}});
    }
    return j;
}

}  // namespace metalfit::glpreview
