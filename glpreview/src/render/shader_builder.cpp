#include "glpreview/render/shader_builder.hpp"

#include <algorithm>
#include <stdexcept>

#include "embedded_shaders.hpp"
#include "glpreview/gl/program_cache.hpp"
#include "libfit/models/model.hpp"

namespace metalfit::glpreview {

ShaderBuilder& ShaderBuilder::define(std::string name, std::string value) {
    std::string label = value.empty() ? name : name + " " + value;
    defines_.push_back({label, "#define " + label});
    return *this;
}

ShaderBuilder& ShaderBuilder::source(std::string_view glsl) {
    if (std::find(sources_.begin(), sources_.end(), std::optional<std::string>(glsl)) == sources_.end())
        sources_.emplace_back(glsl);
    return *this;
}

ShaderBuilder& ShaderBuilder::sampler(std::string name) {
    if (std::find(samplers_.begin(), samplers_.end(), name) == samplers_.end()) samplers_.push_back(std::move(name));
    return *this;
}

ShaderBuilder& ShaderBuilder::fresnel_model(std::string_view id, const Model* model) {
    if (model && model->id() != id)
        throw std::logic_error("ShaderBuilder: model " + std::string(model->id()) + " named " + std::string(id));
    defines_.push_back({"FRESNEL_MODEL " + std::string(id), "#define FRESNEL_MODEL"});
    model_ = model;
    if (!model_chosen_) sources_.emplace_back(std::nullopt);  // the model's GLSL goes here
    model_chosen_ = true;
    return *this;
}

ShaderBuilder& ShaderBuilder::fresnel_reference() {
    define("FRESNEL_REFERENCE");
    return sampler("u_fresnel_lut");
}

ShaderBuilder& ShaderBuilder::radiance(std::string expression) {
    radiance_ = std::move(expression);
    return *this;
}

ShaderBuilder& ShaderBuilder::add_radiance(std::string expression) {
    added_radiance_.push_back(std::move(expression));
    return *this;
}

std::vector<std::string> ShaderBuilder::labels() const {
    std::vector<std::string> labels;
    for (const Define& d : defines_) labels.push_back(d.label);
    std::sort(labels.begin(), labels.end());
    return labels;
}

std::string ShaderBuilder::key() const {
    std::string key = kind_;
    for (const std::string& label : labels()) key += " " + label;
    return key;
}

std::string ShaderBuilder::text() const {
    std::vector<Define> sorted = defines_;
    std::sort(sorted.begin(), sorted.end(), [](const Define& a, const Define& b) { return a.label < b.label; });
    std::string header = "#version 450 core\n";
    for (const Define& d : sorted) header += d.header + "\n";
    if (model_chosen_) {
        if (!model_) throw std::logic_error("ShaderBuilder: " + key() + ": the model is not resolved");
        std::string call = std::string(model_->glsl_function()) + "(";
        for (std::size_t k = 0; k < model_->parameters().size(); ++k) call += "u_param[" + std::to_string(k) + "], ";
        header += "#define FRESNEL_PARAMETERS " + std::to_string(model_->parameters().size()) + "\n";
        header += "#define FRESNEL_CALL " + call + "mu)\n";
    }
    if (!radiance_.empty()) header += "#define SPHERE_RADIANCE " + radiance_ + "\n";
    if (!added_radiance_.empty()) {
        std::string sum;
        for (const std::string& term : added_radiance_) sum += (sum.empty() ? "" : " + ") + term;
        header += "#define SPHERE_ADDED_RADIANCE (" + sum + ")\n";
    }
    std::string body;
    for (const auto& s : sources_) body += s ? *s : model_->glsl_source();
    return header + body;
}

int BuiltProgram::unit(std::string_view sampler) const {
    const auto it = std::find(samplers_.begin(), samplers_.end(), sampler);
    if (it == samplers_.end()) throw std::logic_error("a program reads no sampler '" + std::string(sampler) + "'");
    return static_cast<int>(it - samplers_.begin());
}

bool BuiltProgram::reads(std::string_view sampler) const {
    return std::find(samplers_.begin(), samplers_.end(), sampler) != samplers_.end();
}

void BuiltProgram::bind(std::string_view sampler, GLuint texture) const {
    glBindTextureUnit(static_cast<GLuint>(unit(sampler)), texture);
}

namespace {

bool is_sampler(GLenum type) {
    switch (type) {
        case GL_SAMPLER_1D:
        case GL_SAMPLER_2D:
        case GL_SAMPLER_3D:
        case GL_SAMPLER_CUBE:
        case GL_SAMPLER_1D_SHADOW:
        case GL_SAMPLER_2D_SHADOW:
        case GL_SAMPLER_CUBE_SHADOW:
        case GL_SAMPLER_2D_ARRAY:
        case GL_SAMPLER_CUBE_MAP_ARRAY:
        case GL_SAMPLER_2D_ARRAY_SHADOW:
        case GL_SAMPLER_CUBE_MAP_ARRAY_SHADOW: return true;
        default: return false;
    }
}

// Every sampler the linked program reads must have been declared: an undeclared one would sit on unit 0 beside a
// declared one of another type (a GL error at draw time, or the wrong texture).
void check_samplers_declared(GLuint id, const ShaderBuilder& builder) {
    GLint count = 0;
    glGetProgramiv(id, GL_ACTIVE_UNIFORMS, &count);
    for (GLint i = 0; i < count; ++i) {
        char name[256];
        GLsizei length = 0;
        GLint size = 0;
        GLenum type = 0;
        glGetActiveUniform(id, static_cast<GLuint>(i), sizeof name, &length, &size, &type, name);
        const std::string uniform(name, static_cast<std::size_t>(length));
        if (is_sampler(type) &&
            std::find(builder.samplers().begin(), builder.samplers().end(), uniform) == builder.samplers().end())
            throw std::logic_error("program " + builder.key() + " reads sampler " + uniform +
                                   ", which no effect declared");
    }
}

}  // namespace

BuiltProgram link(ProgramCache& cache, const ShaderBuilder& builder) {
    const std::string key = builder.key();
    const GLuint id = builder.stage() == ShaderBuilder::Stage::compute
                          ? cache.program({{GL_COMPUTE_SHADER, builder.text()}}, key)
                          : cache.program({fullscreen_vertex_stage(), {GL_FRAGMENT_SHADER, builder.text()}}, key);
    check_samplers_declared(id, builder);
    for (std::size_t unit = 0; unit < builder.samplers().size(); ++unit)
        glProgramUniform1i(id, glGetUniformLocation(id, builder.samplers()[unit].c_str()), static_cast<GLint>(unit));
    return {id, builder.samplers()};
}

}  // namespace metalfit::glpreview
