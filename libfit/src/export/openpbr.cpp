// OpenPBR Surface export: a metal is base_metalness 1 with base_color = F0 and specular_color = the F82 tint (OpenPBR's
// F82-tint metal Fresnel), as JSON and as a MaterialX document with open_pbr_surface. Models that are not an F82-tint
// curve (lazanyi-comp, conductor-rgb, gulbrandsen) are written as the material's f82-tint parameters, said so.
#include "export/export_formats.hpp"
#include "export/header_provenance.hpp"
#include "libfit/base/version.hpp"
#include "libfit/fit/fit_record.hpp"
#include "libfit/io/layer_stack.hpp"

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
        for (std::size_t i = 0; i < m.models.size(); ++i) {
            const ModelExport& e = m.models[i];
            const std::string stem = file_stem(context.request.id_prefix, m.fit->material.id, e.written.model->id());
            // A layered material: the base is the bare metal's fit, under OpenPBR's own coat and thin film.
            const MaterialExport& base = base_export(m);
            const ModelExport& be = base.models[i];
            const std::optional<LayeredParameters> layers =
                m.bare_metal ? layered_parameters(m.fit->material) : std::nullopt;
            std::optional<WrittenParameters> f82 = as_f82_tint(be.written, *base.fit->reference);
            std::string note;
            if (!f82) {
                f82 = *be.stand_in;
                note = std::string(e.written.model->id()) +
                       " is not an F82-tint curve: written as the f82-tint parameters (" + f82->origin + "); " +
                       std::string(e.written.model->id()) + "'s own worst-channel rel_rms would be " +
                       number(worst_channel(be.written.metrics.rel_rms)) + ", these parameters' is " +
                       number(worst_channel(f82->metrics.rel_rms));
            }
            const WrittenParameters& w = *f82;
            const Metrics& mt = w.metrics;
            std::string header_note = note;
            if (layers)
                for (const std::string& line : layered_notes(*layers, ExportFormat::openpbr))
                    header_note += (header_note.empty() ? "" : "\n") + line;
            Json j = material_identity_json("metalfit.openpbr/1", m.fit->material, context.record,
                                            e.written.model->id(), layers.has_value());
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
            if (layers) {
                Json& surface = j["open_pbr_surface"];
                if (layers->coat) {
                    surface["coat_weight"] = 1.0;
                    surface["coat_color"] = Json::array({1.0, 1.0, 1.0});
                    surface["coat_roughness"] = 0.0;
                    surface["coat_ior"] = layers->coat_ior;
                }
                if (layers->film) {
                    surface["thin_film_weight"] = 1.0;
                    surface["thin_film_thickness"] = layers->film_thickness_um;
                    surface["thin_film_ior"] = layers->film_ior;
                }
                j["layers"] = {{"base", "the bare metal's fit (" + base.fit->material.name +
                                            ", no layers): the metrics are against its curve"},
                               {"index_at_nm", kLayerIndexWavelengthNm},
                               {"notes", layered_notes(*layers, ExportFormat::openpbr)}};
            }
            j["metrics"] = metrics_record(mt);
            static constexpr std::array<std::string_view, 2> kOpenPbrNames{"base_color", "specular_color"};
            const std::vector<ColourOutOfRange> outside =
                colours_out_of_range(m, w, e.written.model->id(), kOpenPbrNames);
            files.push_back({"openpbr/" + stem + ".json", j.dump(2) + "\n", outside});

            pugi::xml_document doc;
            if (context.materialx_colorspace.empty())
                header_note +=
                    std::string(header_note.empty() ? "" : "\n") + untagged_materialx_warning(context.record.space);
            pugi::xml_node root =
                begin_materialx(doc, comment_header(m, w, context, "  ", header_note, layers.has_value()), context);
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
            if (layers && layers->coat) {
                add_input(s, "coat_weight", "float", "1.0");
                add_input(s, "coat_color", "color3", "1.0, 1.0, 1.0");
                add_input(s, "coat_roughness", "float", "0.0");
                add_input(s, "coat_ior", "float", number(layers->coat_ior));
            }
            if (layers && layers->film) {
                add_input(s, "thin_film_weight", "float", "1.0");
                add_input(s, "thin_film_thickness", "float", number(layers->film_thickness_um));
                add_input(s, "thin_film_ior", "float", number(layers->film_ior));
            }
            add_surface_material(root, stem, shader, false,
                                 comment_header(m, w, context, "", header_note, layers.has_value()));
            files.push_back({"openpbr/" + stem + ".mtlx", xml_text(doc), outside});
        }
    return files;
}

ConsumerCurve openpbr_curve(const MaterialExport& material, const ModelExport& model, GamutPolicy) {
    std::optional<WrittenParameters> f82 = as_f82_tint(model.written, *material.fit->reference);
    const bool own = f82.has_value();
    if (!own) f82 = *model.stand_in;
    return {ExportFormat::openpbr,
            std::string("open_pbr_surface's F82-tint metal (base_color = F0, specular_color = tint)") +
                (own ? "" : " of the stand-in " + std::string(f82->model->id())),
            std::move(f82), ""};
}

}  // namespace metalfit::detail
