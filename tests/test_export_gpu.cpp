// The GLSL model functions (libfit's single definitions, the text every GLSL export carries) evaluated through GL on
// whatever EGL gives (Mesa llvmpipe without a GPU), against the C++ models in double: every catalog material's
// exported parameters (the record export_cpp_tests uses, written by the build), 1025 μ each, within 1e-5.
#include <gtest/gtest.h>

#include <cmath>
#include <fstream>
#include <nlohmann/json.hpp>
#include <string>
#include <vector>

#include "glpreview/gl/gl.hpp"
#include "glpreview/gl/gl_context.hpp"
#include "libfit/models/model.hpp"
#include "test_support.hpp"

namespace test_export_gpu {

using metalfit::glpreview::GlContext;

constexpr int kMu = 1025;  // μ = i / 1024, both ends included

// A compute shader: per invocation one (parameter set, μ); parameters as 4 vec4 per set, F written as vec4.
std::string compute_source(const metalfit::Model& model) {
    std::string call = std::string(model.glsl_function()) + "(";
    for (std::size_t i = 0; i < model.parameters().size(); ++i)
        call += "p[4u * set + " + std::to_string(i) + "u].xyz, ";
    call += "mu)";
    return "#version 450\n" + model.glsl_source() +
           "\nlayout(local_size_x = 64) in;\n"
           "layout(std430, binding = 0) readonly buffer Params { vec4 p[]; };\n"
           "layout(std430, binding = 1) writeonly buffer Values { vec4 f[]; };\n"
           "layout(location = 0) uniform uint count;\n"
           "void main() {\n"
           "    uint i = gl_GlobalInvocationID.x;\n"
           "    if (i >= count) return;\n"
           "    uint set = i / " +
           std::to_string(kMu) +
           "u;\n"
           "    float mu = float(i % " +
           std::to_string(kMu) + "u) / " + std::to_string(kMu - 1) +
           ".0;\n"
           "    f[i] = vec4(" +
           call +
           ", 0.0);\n"
           "}\n";
}

TEST(ExportGlsl, ModelFunctionsOnTheGpuEqualTheCppModels) {
    GlContext context = GlContext::create();
    std::ifstream in(metalfit::test::kCatalogExportJson);
    ASSERT_TRUE(in) << metalfit::test::kCatalogExportJson;
    const auto record = nlohmann::json::parse(in);
    for (const metalfit::Model* model : metalfit::all_models()) {
        SCOPED_TRACE(std::string(model->id()) + " on " + context.renderer());
        // Every material's written parameters for this model.
        std::vector<metalfit::ModelParameters> sets;
        std::vector<float> params;
        for (const auto& [id, material] : record["materials"].items()) {
            const auto& written = material["models"][std::string(model->id())]["export"]["params"];
            metalfit::ModelParameters p;
            for (int slot = 0; slot < 4; ++slot) {
                const bool used = slot < static_cast<int>(model->parameters().size());
                for (int c = 0; c < 3; ++c) {
                    const double v = used ? written[std::string(model->parameters()[slot].name)][c].get<double>() : 0.0;
                    if (used) p[c].push_back(static_cast<float>(v));  // the values the GPU sees
                    params.push_back(static_cast<float>(v));
                }
                params.push_back(0.0f);
            }
            sets.push_back(p);
        }
        ASSERT_EQ(sets.size(), metalfit::test::catalog_material_count());
        const GLuint count = static_cast<GLuint>(sets.size() * kMu);
        const auto program = metalfit::glpreview::compile_compute_program(compute_source(*model), model->id());
        namespace gl = metalfit::glpreview::gl;
        const gl::Buffer input = gl::create_buffer(), output = gl::create_buffer();
        const GLuint buffers[2] = {input.id(), output.id()};
        glNamedBufferStorage(buffers[0], static_cast<GLsizeiptr>(params.size() * sizeof(float)), params.data(), 0);
        glNamedBufferStorage(buffers[1], static_cast<GLsizeiptr>(count * 4 * sizeof(float)), nullptr, GL_MAP_READ_BIT);
        glBindBufferBase(GL_SHADER_STORAGE_BUFFER, 0, buffers[0]);
        glBindBufferBase(GL_SHADER_STORAGE_BUFFER, 1, buffers[1]);
        glUseProgram(program.id());
        glUniform1ui(0, count);
        glDispatchCompute((count + 63) / 64, 1, 1);
        glMemoryBarrier(GL_BUFFER_UPDATE_BARRIER_BIT | GL_CLIENT_MAPPED_BUFFER_BARRIER_BIT);
        std::vector<float> gpu(count * 4);
        glGetNamedBufferSubData(buffers[1], 0, static_cast<GLsizeiptr>(gpu.size() * sizeof(float)), gpu.data());
        metalfit::glpreview::check_gl("export GPU check");

        double worst = 0;
        for (std::size_t s = 0; s < sets.size(); ++s)
            for (int i = 0; i < kMu; ++i) {
                const double mu = static_cast<double>(static_cast<float>(i / double(kMu - 1)));
                const metalfit::RGB cpp = model->evaluate(sets[s], mu);
                for (int c = 0; c < 3; ++c) {
                    const double d = std::abs(gpu[(s * kMu + i) * 4 + c] - cpp[c]);
                    worst = std::max(worst, d);
                    ASSERT_LE(d, 1e-5) << "set " << s << " mu " << mu << " channel " << c;
                }
            }
        std::printf("export GLSL on GL (%s): %s worst |GPU - C++| = %.3g over %d materials x %d mu\n",
                    context.renderer().c_str(), std::string(model->id()).c_str(), worst, static_cast<int>(sets.size()),
                    kMu);
    }
}

}  // namespace test_export_gpu
