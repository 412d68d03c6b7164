#include "reflection_effect.hpp"

#include <stdexcept>

#include "glpreview/gl/uniforms.hpp"
#include "glpreview/render/gpu_renderer.hpp"
#include "render/embedded_shaders.hpp"

namespace metalfit::glpreview {

void declare_reflection_lookup(const Sphere& sphere, ShaderBuilder& builder) {
    switch (sphere.reflection) {
        case ReflectionMode::classic: builder.define("REFLECTION_CLASSIC"); break;
        case ReflectionMode::box_parallax: builder.define("REFLECTION_BOX_PARALLAX"); break;
        case ReflectionMode::distance_impostor:
            builder.define("REFLECTION_DISTANCE_IMPOSTOR")
                .define(strategy_define(sphere.strategy))
                .define("NITER", std::to_string(sphere.iterations))
                .define("SEARCH_STEPS", std::to_string(sphere.search_steps))
                .define("TOLERANCE", glsl_float(sphere.tolerance));
            break;
    }
    builder.source(shader_text("reflection.glsl")).sampler("u_env");
}

namespace {

class ReflectionEffect final : public Effect {
public:
    std::string_view name() const override { return "reflection"; }

    std::vector<const char*> sphere_keys() const override {
        return {"reflection", "strategy", "iterations", "tolerance", "search_steps"};
    }

    void read_sphere(const SceneReader& r, Sphere& s, Scene& scene) const override {
        r.read_enum("reflection", s.reflection, kReflectionModeNames);
        r.read_enum("strategy", s.strategy, kStrategyNames);
        r.read("iterations", s.iterations, 0, 64);
        r.read("tolerance", s.tolerance, 0, 1);
        r.read("search_steps", s.search_steps, 0, 64);
        if (r.has("search_steps") && s.reflection == ReflectionMode::distance_impostor &&
            s.strategy != Strategy::illinois && s.strategy != Strategy::safe_secant)
            scene.warnings.push_back(r.file().string() + ": " + r.field("search_steps") +
                                     ": ignored: the thesis's strategy '" + to_string(s.strategy) +
                                     "' is kept as described (only illinois and safe-secant search first)");
        if (s.reflection != ReflectionMode::distance_impostor)
            for (const char* key : {"strategy", "iterations", "tolerance", "search_steps"})
                if (r.has(key))
                    scene.warnings.push_back(r.file().string() + ": " + r.field(key) +
                                             ": ignored: only the distance impostor refines (reflection '" +
                                             to_string(s.reflection) + "')");
        if (s.reflection != ReflectionMode::classic && !scene.environment.captured())
            r.fail(r.field("reflection"),
                   "an equirect environment is at infinity without a proxy: only 'classic' reflections");
        if (s.reflection == ReflectionMode::box_parallax && !scene.environment.parallax_box())
            r.fail(r.field("reflection"), "box-parallax needs a room environment or an equirect with a box proxy");
    }

    void declare_sphere(const SphereShader& shader, ShaderBuilder& builder) const override {
        declare_reflection_lookup(shader.sphere, builder);
    }
};

}  // namespace

const Effect& reflection_effect() {
    static const ReflectionEffect effect;
    return effect;
}

std::vector<ProbeResult> probe_reflection_lookups(GpuRenderer& renderer, const Sphere& settings,
                                                  std::span<const std::array<Vec3, 2>> rays) {
    if (!renderer.cube()) throw std::logic_error("probe_reflection_lookups: no captured cube map");
    ShaderBuilder probe("probe", ShaderBuilder::Stage::compute);
    declare_environment(renderer.scene(), probe);
    declare_reflection_lookup(settings, probe);
    probe.source(shader_text("probe.comp"));
    const BuiltProgram& p = renderer.program(probe);
    const int count = static_cast<int>(rays.size());
    set_uniform(p.id(), "u_count", count);
    std::vector<float> input;
    for (const auto& [x, r] : rays)
        input.insert(input.end(), {float(x.x), float(x.y), float(x.z), 0.f, float(r.x), float(r.y), float(r.z), 0.f});
    const gl::Buffer input_buffer = gl::create_buffer(), output_buffer = gl::create_buffer();
    const GLuint buffers[2] = {input_buffer.id(), output_buffer.id()};
    glNamedBufferStorage(buffers[0], static_cast<GLsizeiptr>(input.size() * sizeof(float)), input.data(), 0);
    glNamedBufferStorage(buffers[1], static_cast<GLsizeiptr>(input.size() * sizeof(float)), nullptr, GL_MAP_READ_BIT);
    glBindBufferBase(GL_SHADER_STORAGE_BUFFER, 0, buffers[0]);
    glBindBufferBase(GL_SHADER_STORAGE_BUFFER, 1, buffers[1]);
    p.bind("u_env", renderer.cube()->texture.id());
    glUseProgram(p.id());
    glDispatchCompute(static_cast<GLuint>((count + 63) / 64), 1, 1);
    glMemoryBarrier(GL_BUFFER_UPDATE_BARRIER_BIT);
    std::vector<float> output(input.size());
    glGetNamedBufferSubData(buffers[1], 0, static_cast<GLsizeiptr>(output.size() * sizeof(float)), output.data());
    check_gl("probing reflection lookups");
    std::vector<ProbeResult> results;
    for (int i = 0; i < count; ++i) {
        const float* v = &output[8 * static_cast<std::size_t>(i)];
        results.push_back({{v[0], v[1], v[2]}, {v[4], v[5], v[6], v[7]}, static_cast<int>(v[3])});
    }
    return results;
}

}  // namespace metalfit::glpreview
