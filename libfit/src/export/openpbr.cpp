// OpenPBR Surface export: a metal is base_metalness 1 with base_color = F0 and specular_color = the F82 tint (OpenPBR's
// F82-tint metal Fresnel), as JSON and as a MaterialX document with open_pbr_surface. Models that are not an F82-tint
// curve (lazanyi-comp, conductor-rgb, gulbrandsen) are written as the material's f82-tint parameters, said so.
#include "export/export_formats.hpp"
#include "export/header_provenance.hpp"
#include "libfit/base/version.hpp"
#include "libfit/fit/fit_record.hpp"

namespace metalfit::detail {

namespace {

using Json = nlohmann::ordered_json;

Json colour(const ModelParameters& p, std::size_t i) {
    const RGB v = p.parameter(i);
    return Json::array({v.r, v.g, v.b});
}

}  // namespace

std::vector<ExportFile> export_openpbr(const std::vector<MaterialExport>& materials, const ExportContext& context) {
    std::vector<ExportFile> files;
    for (const MaterialExport& m : materials)
        for (const ModelExport& e : m.models) {
            const std::string stem = file_stem(context.request.id_prefix, m.fit->material.id, e.written.model->id());
            std::optional<WrittenParameters> f82 = as_f82_tint(e.written, *m.fit->reference);
            std::string note;
            if (!f82) {
                f82 = *e.stand_in;
                note = std::string(e.written.model->id()) +
                       " is not an F82-tint curve: written as the f82-tint parameters (" + f82->origin + "); " +
                       std::string(e.written.model->id()) + "'s own worst-channel rel_rms would be " +
                       number(worst_channel(e.written.metrics.rel_rms)) + ", these parameters' is " +
                       number(worst_channel(f82->metrics.rel_rms));
            }
            const WrittenParameters& w = *f82;
            const Metrics& mt = w.metrics;
            Json j =
                material_identity_json("metalfit.openpbr/1", m.fit->material, context.record, e.written.model->id());
            j["written_as"] = "f82-tint";
            j["from"] = w.origin;
            j["note"] = note;
            j["gamut"] = to_string(context.request.gamut);
            j["out_of_gamut"] = w.gamut;
            j["open_pbr_surface"] = {{"base_weight", 1.0},
                                     {"base_color", colour(w.params, 0)},
                                     {"base_metalness", 1.0},
                                     {"specular_weight", 1.0},
                                     {"specular_color", colour(w.params, 1)},
                                     {"specular_roughness", context.request.roughness}};
            j["metrics"] = metrics_record(mt);
            files.push_back({"openpbr/" + stem + ".json", j.dump(2) + "\n"});

            pugi::xml_document doc;
            if (context.materialx_colorspace.empty())
                note += std::string(note.empty() ? "" : "\n") + untagged_materialx_warning(context.record.space);
            pugi::xml_node root = begin_materialx(doc, comment_header(m, w, context, "  ", note), context);
            const std::string shader = stem + "_open_pbr_surface";
            pugi::xml_node s = root.append_child("open_pbr_surface");
            s.append_attribute("name") = shader.c_str();
            s.append_attribute("type") = "surfaceshader";
            add_input(s, "base_weight", "float", "1.0");
            add_input(s, "base_color", "color3", channel_list(w.params, 0));
            add_input(s, "base_metalness", "float", "1.0");
            add_input(s, "specular_weight", "float", "1.0");
            add_input(s, "specular_color", "color3", channel_list(w.params, 1));
            add_input(s, "specular_roughness", "float", number(context.request.roughness));
            add_surface_material(root, stem, shader, false, comment_header(m, w, context, "", note));
            files.push_back({"openpbr/" + stem + ".mtlx", xml_text(doc)});
        }
    return files;
}

}  // namespace metalfit::detail
