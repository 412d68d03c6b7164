// GLSL export: glsl/metalfit_models.glsl holds the model functions, exactly the text of the model folders (glsl_library);
// glsl/<material>_<model>.glsl the constants of one material and model and a function of μ alone.
#include <cctype>

#include "export/export_formats.hpp"
#include "libfit/base/version.hpp"

namespace metalfit::detail {

std::string shader_constants(const MaterialExport& material, const ModelExport& model, const ExportContext& context,
                             const ShaderSyntax& syntax) {
    const WrittenParameters& w = model.written;
    const std::string& prefix = context.request.id_prefix;
    const std::string id = constant_stem(prefix, material.fit->material.id, w.model->id());
    std::string text = comment_header(material, w, context, "// ");
    text +=
        "// Needs " + std::string(syntax.models_file) + " before this file; F(mu), mu = cos(theta), per RGB channel.\n";
    text += "// " + std::string(syntax.language) +
            ". Constants: the float nearest each fitted value (at most 9 significant\n"
            "// digits, the float's shortest round trip); the figures above are of the fitted doubles.\n";
    text += half_precision_note(w, "// ");
    const std::string guard = id + "_" + std::string(syntax.extension);
    text += "#ifndef " + guard + "  // the file may be included more than once\n#define " + guard + "\n";
    std::string args;
    std::string locals;
    const auto parameters = w.model->parameters();
    for (std::size_t i = 0; i < parameters.size(); ++i) {
        std::string name(parameters[i].name);
        for (char& ch : name) ch = static_cast<char>(std::toupper(static_cast<unsigned char>(ch)));
        const std::string constant = id + "_" + name;
        text += std::string(syntax.constant) + " " + constant + " = " + std::string(syntax.vector) + "(" +
                shader_channel_list(w.params, i) + ");\n";
        if (syntax.copy_to_locals) {
            locals +=
                "    " + std::string(syntax.vector) + " " + std::string(parameters[i].name) + " = " + constant + ";\n";
            args += std::string(parameters[i].name) + ", ";
        } else {
            args += constant + ", ";
        }
    }
    text += std::string(syntax.vector) + " " + file_stem(prefix, material.fit->material.id, w.model->id()) +
            "(float mu) {\n" + locals + "    return " + std::string(w.model->glsl_function()) + "(" + args +
            "mu);\n}\n#endif  // " + guard + "\n";
    return text;
}

std::string glsl_models_file(const std::vector<const Model*>& models) {
    return "// metalfit " METALFIT_VERSION
           " Fresnel models: the GLSL of libfit/models, unchanged (`metalfit models --glsl`).\n"
           "// F(mu), mu = cos(theta), per RGB channel. Paste after #version: GLSL >= 1.30 (tested as 3.30 and 4.50) or\n"
           "// GLSL ES 3.00 (WebGL 2). GLSL ES has no default float precision in fragment shaders: the block below asks\n"
           "// for highp, which the models need (half precision: see each material's file).\n"
           "#ifdef GL_ES\nprecision highp float;\n#endif\n" +
           glsl_library(models);
}

std::vector<ExportFile> export_glsl(const std::vector<MaterialExport>& materials, const ExportContext& context) {
    static constexpr ShaderSyntax kGlsl{"const vec3",
                                        "vec3",
                                        "metalfit_models.glsl",
                                        "GLSL >= 1.30 (tested as 3.30 and 4.50) or GLSL ES 3.00 (WebGL 2)",
                                        "GLSL",
                                        false};
    std::vector<ExportFile> files;
    files.push_back({"glsl/metalfit_models.glsl", glsl_models_file(context.request.models)});
    for (const MaterialExport& m : materials)
        for (const ModelExport& e : m.models)
            files.push_back(
                {"glsl/" + file_stem(context.request.id_prefix, m.fit->material.id, e.written.model->id()) + ".glsl",
                 shader_constants(m, e, context, kGlsl), colours_out_of_range(m, e.written, e.written.model->id())});
    return files;
}

}  // namespace metalfit::detail
