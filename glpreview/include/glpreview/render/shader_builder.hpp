// A GL program assembled from what the effects declare (OpenColorIO's GpuShaderCreator is the pattern): its #defines,
// its GLSL in order, the textures it samples and the Fresnel as a typed choice. The builder assigns the texture
// units (in the order the samplers are declared) and names the variant; nothing else fixes a unit or parses a
// define back. It needs no GL: the plan names the variants a scene compiles from builders alone.
#pragma once

#include <optional>
#include <string>
#include <string_view>
#include <vector>

#include "glpreview/gl/gl.hpp"

namespace metalfit {
class Model;
}

namespace metalfit::glpreview {

class ProgramCache;

class ShaderBuilder {
public:
    enum class Stage { fragment, compute };  // a full-screen fragment pass, or a compute program
    explicit ShaderBuilder(std::string kind, Stage stage = Stage::fragment) : kind_(std::move(kind)), stage_(stage) {}

    // "#define NAME [VALUE]": part of the variant's name (the sorted labels) and of the header.
    ShaderBuilder& define(std::string name, std::string value = {});
    // GLSL appended to the body in order; a text already added is not added again (shared functions). The model's
    // GLSL (fresnel_model) goes where the model was chosen, before the sources that call it.
    ShaderBuilder& source(std::string_view glsl);
    // A sampler uniform the program reads; it gets the next texture unit.
    ShaderBuilder& sampler(std::string name);
    // The Fresnel of a sphere as a typed choice: a libfit model (its GLSL, its call on
    // u_param[FRESNEL_PARAMETERS], one vec3 per parameter: any parameter count; named "FRESNEL_MODEL <id>") or the
    // exact reference curve (sampler u_fresnel_lut; named FRESNEL_REFERENCE). `model` may be null while only the
    // variant's name is wanted (planning); text() then refuses.
    ShaderBuilder& fresnel_model(std::string_view id, const Model* model);
    ShaderBuilder& fresnel_reference();
    // What the sphere shader's main() writes: the radiance of the sphere's one lobe (mirror, glossy, diagnostics), an
    // expression in main()'s locals; a later effect replaces an earlier one. Not part of the name (it follows from
    // the defines that chose it).
    ShaderBuilder& radiance(std::string expression);
    // A term added to that radiance (lights, later effects); none: nothing is added, not even zero.
    ShaderBuilder& add_radiance(std::string expression);

    const std::string& kind() const { return kind_; }
    Stage stage() const { return stage_; }
    std::vector<std::string> labels() const;  // the defines as named, sorted ("NITER 8", "FRESNEL_MODEL f82-tint")
    std::string key() const;                  // kind and labels: "sphere ENV_ROOM FRESNEL_REFERENCE ..."
    std::string text() const;                 // the complete source, #version line included
    const std::vector<std::string>& samplers() const { return samplers_; }

private:
    struct Define {
        std::string label;   // as named
        std::string header;  // as written ("#define FRESNEL_MODEL")
    };
    std::string kind_;
    Stage stage_;
    std::vector<Define> defines_;
    std::vector<std::optional<std::string>> sources_;  // nullopt: the model's GLSL
    std::vector<std::string> samplers_;
    const Model* model_ = nullptr;
    bool model_chosen_ = false;
    std::string radiance_;
    std::vector<std::string> added_radiance_;
};

// A linked program and the texture units its builder assigned.
class BuiltProgram {
public:
    BuiltProgram() = default;
    BuiltProgram(GLuint id, std::vector<std::string> samplers) : id_(id), samplers_(std::move(samplers)) {}
    GLuint id() const { return id_; }
    const std::vector<std::string>& samplers() const { return samplers_; }
    bool reads(std::string_view sampler) const;
    // The unit of a declared sampler; std::logic_error for one the program did not declare.
    int unit(std::string_view sampler) const;
    // Binds `texture` to the unit of `sampler`.
    void bind(std::string_view sampler, GLuint texture) const;

private:
    GLuint id_ = 0;
    std::vector<std::string> samplers_;
};

// Links the builder's program through the cache (once per distinct text) and sets each sampler to its unit.
BuiltProgram link(ProgramCache& cache, const ShaderBuilder& builder);

}  // namespace metalfit::glpreview
