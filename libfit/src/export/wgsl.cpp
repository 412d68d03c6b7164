// WGSL export (WebGPU): wgsl/metalfit_models.wgsl holds the model functions, the text of the .wgsl files beside each
// model's GLSL (wgsl_library); wgsl/<material>_<model>.wgsl the constants of one material and model and a function
// of μ alone. WGSL has no #include: a shader is the models file followed by the material files it uses.
#include <cctype>

#include "export/export_formats.hpp"
#include "libfit/base/version.hpp"

namespace metalfit::detail {

std::string wgsl_models_file(const std::vector<const Model*>& models) {
    return "// metalfit " METALFIT_VERSION
           " Fresnel models for WebGPU: the WGSL beside the GLSL of libfit/models, unchanged.\n"
           "// F(mu), mu = cos(theta), per RGB channel. WGSL has no #include: put this text once before the material\n"
           "// files (docs/export.md).\n" +
           wgsl_library(models);
}

namespace {

std::string wgsl_constants(const MaterialExport& material, const ModelExport& model, const ExportContext& context) {
    const WrittenParameters& w = model.written;
    const std::string& prefix = context.request.id_prefix;
    const std::string id = constant_stem(prefix, material.fit->material.id, w.model->id());
    std::string text = comment_header(material, w, context, "// ");
    text += "// Needs metalfit_models.wgsl before this text (once); F(mu), mu = cos(theta), per RGB channel.\n";
    text += "// WGSL (WebGPU). Constants: the float nearest each fitted value (at most 9 significant\n"
            "// digits, the float's shortest round trip); the figures above are of the fitted doubles.\n";
    text += half_precision_note(w, "// ");
    std::string args;
    const auto parameters = w.model->parameters();
    for (std::size_t i = 0; i < parameters.size(); ++i) {
        std::string name(parameters[i].name);
        for (char& ch : name) ch = static_cast<char>(std::toupper(static_cast<unsigned char>(ch)));
        const std::string constant = id + "_" + name;
        text += "const " + constant + " = vec3f(" + shader_channel_list(w.params, i) + ");\n";
        args += constant + ", ";
    }
    text += "fn " + file_stem(prefix, material.fit->material.id, w.model->id()) + "(mu: f32) -> vec3f {\n    return " +
            std::string(w.model->glsl_function()) + "(" + args + "mu);\n}\n";
    return text;
}

}  // namespace

std::vector<ExportFile> export_wgsl(const std::vector<MaterialExport>& materials, const ExportContext& context) {
    std::vector<ExportFile> files;
    files.push_back({"wgsl/metalfit_models.wgsl", wgsl_models_file(context.request.models)});
    for (const MaterialExport& m : materials)
        for (const ModelExport& e : m.models)
            files.push_back(
                {"wgsl/" + file_stem(context.request.id_prefix, m.fit->material.id, e.written.model->id()) + ".wgsl",
                 wgsl_constants(m, e, context), colours_out_of_range(m, e.written, e.written.model->id())});
    return files;
}

}  // namespace metalfit::detail
