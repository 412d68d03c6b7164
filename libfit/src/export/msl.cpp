// MSL export (Metal Shading Language 2.0): msl/metalfit_models.metal holds the model functions as SPIRV-Cross
// translated them from the models' GLSL at build time (glslangValidator → SPIR-V → spirv-cross --msl,
// cmake/MslFromGlsl.cmake); msl/<material>_<model>.metal the constants of one material and model and a function of μ.
#include <stdexcept>

#include "export/export_formats.hpp"
#include "libfit/base/version.hpp"
#include "shader_files.hpp"

namespace metalfit::detail {

namespace {

// The names of the functions a GLSL file defines ("vec3 metalfit_schlick(" at the start of a line), in its order.
std::vector<std::string> glsl_function_names(std::string_view glsl) {
    std::vector<std::string> names;
    constexpr std::string_view kStart = "\nvec3 ";
    const std::string text = "\n" + std::string(glsl);
    for (std::size_t at = text.find(kStart); at != std::string::npos; at = text.find(kStart, at + 1)) {
        const std::size_t begin = at + kStart.size();
        const std::size_t paren = text.find('(', begin);
        if (paren != std::string::npos) names.push_back(text.substr(begin, paren - begin));
    }
    return names;
}

// SPIRV-Cross's definition of one function: from its `static inline` line to the closing brace.
std::string_view msl_function(std::string_view name) {
    const std::string signature = "\nfloat3 " + std::string(name) + "(";
    const std::size_t at = kMslTranslation.find(signature);
    constexpr std::string_view kInline = "static inline __attribute__((always_inline))";
    const std::size_t begin = at == std::string_view::npos ? at : kMslTranslation.rfind(kInline, at);
    const std::size_t end = at == std::string_view::npos ? at : kMslTranslation.find("\n}\n", at);
    if (begin == std::string_view::npos || end == std::string_view::npos)
        throw std::logic_error("SPIRV-Cross's MSL has no function " + std::string(name));
    return kMslTranslation.substr(begin, end + 3 - begin);
}

std::string upper(std::string_view s) {
    std::string out(s);
    for (char& c : out) c = static_cast<char>(std::toupper(static_cast<unsigned char>(c)));
    return out;
}

}  // namespace

std::string msl_models_file(const std::vector<const Model*>& models) {
    std::string text = "// metalfit " METALFIT_VERSION
                       " Fresnel models in the Metal Shading Language 2.0: SPIRV-Cross's translation of the GLSL\n"
                       "// of libfit/models (glslangValidator compiles it to SPIR-V, spirv-cross --msl translates that;"
                       " docs/export.md).\n// F(mu), mu = cos(theta), per RGB channel; comments are in the GLSL"
                       " (`metalfit models --glsl`).\n#include <metal_stdlib>\nusing namespace metal;\n";
    for (std::string_view file : shader_file_names(models)) {
        const std::string guard = "METALFIT_" + upper(file) + "_MSL";
        text += "\n#ifndef " + guard + "  // the file may be included more than once\n#define " + guard + "\n";
        bool first = true;
        for (const std::string& name : glsl_function_names(shader_file(file))) {
            if (!first) text += '\n';
            first = false;
            text += msl_function(name);
        }
        text += "#endif  // " + guard + "\n";
    }
    return text;
}

std::vector<ExportFile> export_msl(const std::vector<MaterialExport>& materials, const ExportContext& context) {
    static constexpr ShaderSyntax kMsl{"constant float3",
                                       "float3",
                                       "metalfit_models.metal",
                                       "Metal Shading Language 2.0 (SPIRV-Cross's translation of the GLSL)",
                                       "MSL",
                                       true};
    std::vector<ExportFile> files;
    files.push_back({"msl/metalfit_models.metal", msl_models_file(context.request.models)});
    for (const MaterialExport& m : materials)
        for (const ModelExport& e : m.models)
            files.push_back(
                {"msl/" + file_stem(context.request.id_prefix, m.fit->material.id, e.written.model->id()) + ".metal",
                 shader_constants(m, e, context, kMsl), colours_out_of_range(m, e.written, e.written.model->id())});
    return files;
}

}  // namespace metalfit::detail
