// HLSL export: the GLSL of the model folders translated mechanically (a prelude of helpers plus a token mapping, so there
// is no second copy of any model), and per-material constants as `static const float3`.
#include <cctype>
#include <map>

#include "export/export_formats.hpp"
#include "libfit/base/version.hpp"

namespace metalfit {

namespace {

// GLSL built-ins the model functions use that HLSL spells differently or lacks, defined with HLSL built-ins.
constexpr std::string_view kHlslPrelude =
    R"hlsl(// metalfit: GLSL constructs of the model functions, for HLSL (docs/export.md). vec3(s) splats a scalar, which HLSL's
// float3(s) does not; mix with a bool3 selects per component; greaterThanEqual / equal compare per component.
#ifndef METALFIT_HLSL_PRELUDE  // the file may be included more than once
#define METALFIT_HLSL_PRELUDE
float3 metalfit_vec3(float s) { return float3(s, s, s); }
float3 metalfit_vec3(float x, float y, float z) { return float3(x, y, z); }
float3 metalfit_vec3(float3 v) { return v; }
float3 metalfit_mix(float3 a, float3 b, bool3 t) { return float3(t.x ? b.x : a.x, t.y ? b.y : a.y, t.z ? b.z : a.z); }
float3 metalfit_mix(float3 a, float3 b, float3 t) { return lerp(a, b, t); }
float3 metalfit_mix(float3 a, float3 b, float t) { return lerp(a, b, t); }
bool3 metalfit_greaterThanEqual(float3 a, float3 b) { return bool3(a.x >= b.x, a.y >= b.y, a.z >= b.z); }
bool3 metalfit_equal(float3 a, float3 b) { return bool3(a.x == b.x, a.y == b.y, a.z == b.z); }
#endif  // METALFIT_HLSL_PRELUDE
)hlsl";

bool identifier_start(char c) { return std::isalpha(static_cast<unsigned char>(c)) || c == '_'; }
bool identifier_char(char c) { return std::isalnum(static_cast<unsigned char>(c)) || c == '_'; }

}  // namespace

std::string hlsl_from_glsl(std::string_view glsl) {
    static const std::map<std::string_view, std::string_view> kTokens{
        {"bvec3", "bool3"},
        {"mix", "metalfit_mix"},
        {"greaterThanEqual", "metalfit_greaterThanEqual"},
        {"equal", "metalfit_equal"},
    };
    std::string out;
    std::size_t i = 0;
    while (i < glsl.size()) {
        const char c = glsl[i];
        if (glsl.substr(i, 2) == "//") {  // comments are copied unchanged
            const std::size_t end = glsl.find('\n', i);
            const std::size_t stop = end == std::string_view::npos ? glsl.size() : end;
            out += glsl.substr(i, stop - i);
            i = stop;
        } else if (glsl.substr(i, 2) == "/*") {
            const std::size_t end = glsl.find("*/", i + 2);
            const std::size_t stop = end == std::string_view::npos ? glsl.size() : end + 2;
            out += glsl.substr(i, stop - i);
            i = stop;
        } else if (std::isdigit(static_cast<unsigned char>(c)) ||
                   (c == '.' && i + 1 < glsl.size() && std::isdigit(static_cast<unsigned char>(glsl[i + 1])))) {
            // A number, exponent included (1e-30), copied as it is.
            std::size_t j = i;
            while (j < glsl.size() &&
                   (identifier_char(glsl[j]) || glsl[j] == '.' ||
                    ((glsl[j] == '-' || glsl[j] == '+') && (glsl[j - 1] == 'e' || glsl[j - 1] == 'E'))))
                ++j;
            out += glsl.substr(i, j - i);
            i = j;
        } else if (identifier_start(c)) {
            std::size_t j = i;
            while (j < glsl.size() && identifier_char(glsl[j])) ++j;
            const std::string_view token = glsl.substr(i, j - i);
            if (token == "vec3") {
                std::size_t k = j;
                while (k < glsl.size() && (glsl[k] == ' ' || glsl[k] == '\t')) ++k;
                out += k < glsl.size() && glsl[k] == '(' ? "metalfit_vec3" : "float3";  // constructor or type
            } else if (const auto it = kTokens.find(token); it != kTokens.end()) {
                out += it->second;
            } else {
                out += token;
            }
            i = j;
        } else {
            out += c;
            ++i;
        }
    }
    return std::string(kHlslPrelude) + "\n" + out;
}

namespace detail {

std::string hlsl_models_file(const std::vector<const Model*>& models) {
    return "// metalfit " METALFIT_VERSION
           " Fresnel models for HLSL: the GLSL of libfit/models translated mechanically "
           "(prelude + token mapping, docs/export.md).\n// F(mu), mu = cos(theta), per RGB channel.\n" +
           hlsl_from_glsl(glsl_library(models));
}

std::vector<ExportFile> export_hlsl(const std::vector<MaterialExport>& materials, const ExportContext& context) {
    static constexpr ShaderSyntax kHlsl{"static const float3",
                                        "float3",
                                        "metalfit_models.hlsl",
                                        "HLSL (tested with glslangValidator's HLSL front end, compute stage)",
                                        "HLSL",
                                        false};
    std::vector<ExportFile> files;
    files.push_back({"hlsl/metalfit_models.hlsl", hlsl_models_file(context.request.models)});
    for (const MaterialExport& m : materials)
        for (const ModelExport& e : m.models)
            files.push_back(
                {"hlsl/" + file_stem(context.request.id_prefix, m.fit->material.id, e.written.model->id()) + ".hlsl",
                 shader_constants(m, e, context, kHlsl), colours_out_of_range(m, e.written, e.written.model->id())});
    return files;
}

}  // namespace detail
}  // namespace metalfit
