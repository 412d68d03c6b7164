// MaterialX 1.39 export (pugixml), by each model's MaterialX form (a trait, libfit/models/registry.hpp): F82-tint
// curves (f82-tint, schlick, lazanyi) as generalized_schlick_bsdf (color0 = F0, color82 = tint, exponent 5: the same
// curve), n, k models (conductor-rgb) as conductor_bsdf (ior = n, extinction = k), r, g models (gulbrandsen) as
// artistic_ior feeding conductor_bsdf, and models MaterialX cannot express (lazanyi-comp) as their closest
// expressible stand-in (the f82-tint fit). Each BSDF is wrapped in surface + surfacematerial.
#include <algorithm>
#include <sstream>
#include <stdexcept>

#include "export/export_formats.hpp"

namespace metalfit::detail {

namespace {

// MaterialX's artistic_ior clamps reflectivity to [0, 0.99] in every shading language it generates.
constexpr double kArtisticIorMaxReflectivity = 0.99;

std::string no_double_hyphen(std::string s) {  // "--" may not appear in an XML comment
    for (std::size_t p = s.find("--"); p != std::string::npos; p = s.find("--", p)) s.replace(p, 2, "- -");
    return s;
}

std::string colour3(const ModelParameters& params, std::size_t index) { return channel_list(params, index); }

// The parameters MaterialX receives for one model, by the model's MaterialX form, and the note saying what changed.
WrittenParameters materialx_parameters(const MaterialExport& m, const ModelExport& e, std::string& extra) {
    const Model& model = *e.written.model;
    WrittenParameters w = e.written;
    switch (model.materialx_form()) {
        case MaterialxForm::generalized_schlick: return *as_f82_tint(e.written, *m.fit->reference);
        case MaterialxForm::stand_in:
            w = *e.stand_in;
            extra = std::string(model.id()) + " has no MaterialX form (" +
                    std::string(model.materialx_stand_in_reason()) + "): written as its closest\nexpressible fit, " +
                    std::string(w.model->id()) + " in generalized_schlick_bsdf (exponent 5); " +
                    std::string(model.id()) + "'s own worst-channel rel_rms\nwould be " +
                    number(worst_channel(e.written.metrics.rel_rms)) + ", this stand-in's is " +
                    number(worst_channel(w.metrics.rel_rms)) + "; the figures below are the stand-in's.";
            return w;
        case MaterialxForm::artistic_ior: {
            RGB reflectivity = w.params.parameter(0);
            bool clamped = false;
            for (int c = 0; c < 3; ++c)
                if (reflectivity[c] > kArtisticIorMaxReflectivity)
                    reflectivity[c] = kArtisticIorMaxReflectivity, clamped = true;
            if (clamped) {
                w.params.set_parameter(0, reflectivity);
                w.metrics = compute_metrics(*w.model, w.params, *m.fit->reference);
                w.gamut.push_back(std::string(model.parameters()[0].name) +
                                  " above 0.99, which MaterialX's artistic_ior clamps to 0.99: written as 0.99");
            }
            return w;
        }
        case MaterialxForm::conductor_bsdf: return w;
    }
    throw std::logic_error("materialx_parameters: unknown MaterialX form");
}

pugi::xml_node append_bsdf(pugi::xml_node root, const char* category, const std::string& name) {
    pugi::xml_node n = root.append_child(category);
    n.append_attribute("name") = name.c_str();
    n.append_attribute("type") = "BSDF";
    return n;
}

std::string document(const MaterialExport& m, std::size_t model_index, const ExportContext& context,
                     std::vector<ColourOutOfRange>& outside) {
    const std::string& ocio_space = context.record.space;
    const ModelExport& e = m.models[model_index];
    const std::string stem = file_stem(context.request.id_prefix, m.fit->material.id, e.written.model->id());
    // A layered material: the metal's BSDF is the bare metal's fit, under MaterialX's own coat layer and thin film.
    const MaterialExport& base = base_export(m);
    const std::optional<LayeredParameters> layers = m.bare_metal ? layered_parameters(m.fit->material) : std::nullopt;
    std::string extra;
    const WrittenParameters w = materialx_parameters(base, base.models[model_index], extra);
    static constexpr std::array<std::string_view, 2> kSchlickNames{"color0", "color82"};
    static constexpr std::array<std::string_view, 2> kArtisticNames{"reflectivity", "edge_color"};
    outside = colours_out_of_range(m, w, e.written.model->id(),
                                   w.model->materialx_form() == MaterialxForm::artistic_ior
                                       ? std::span<const std::string_view>(kArtisticNames)
                                       : std::span<const std::string_view>(kSchlickNames));
    if (layers)
        for (const std::string& line : layered_notes(*layers, ExportFormat::mtlx))
            extra += std::string(extra.empty() ? "" : "\n") + line;
    if (context.materialx_colorspace.empty())
        extra += std::string(extra.empty() ? "" : "\n") + untagged_materialx_warning(ocio_space);
    pugi::xml_document doc;
    const bool base_of_layers = layers.has_value();
    pugi::xml_node root = begin_materialx(doc, comment_header(m, w, context, "  ", extra, base_of_layers), context);
    const std::string provenance = comment_header(m, w, context, "", extra, base_of_layers);
    const std::string bsdf = stem + "_bsdf";
    // The perceptual roughness as OpenPBR takes it; roughness_anisotropy makes MaterialX's α = R² of it.
    const std::string roughness = stem + "_roughness";
    pugi::xml_node r = root.append_child("roughness_anisotropy");
    r.append_attribute("name") = roughness.c_str();
    r.append_attribute("type") = "vector2";
    add_input(r, "roughness", "float", number(context.request.roughness));
    const auto add_roughness = [&](pugi::xml_node n) {
        pugi::xml_node in = n.append_child("input");
        in.append_attribute("name") = "roughness";
        in.append_attribute("type") = "vector2";
        in.append_attribute("nodename") = roughness.c_str();
        // A thin film over the metal: MaterialX 1.39's thinfilm inputs of the metal's BSDF (its 1.38 thin_film_bsdf
        // node layered over the conductor became these inputs), the thickness in nanometres.
        if (layers && layers->film) {
            add_input(n, "thinfilm_thickness", "float", number(layers->film_thickness_nm));
            add_input(n, "thinfilm_ior", "float", number(layers->film_ior));
        }
    };
    switch (w.model->materialx_form()) {
        case MaterialxForm::generalized_schlick:
        case MaterialxForm::stand_in: {  // a stand-in is written as the stand-in model (generalized_schlick)
            pugi::xml_node n = append_bsdf(root, "generalized_schlick_bsdf", bsdf);
            add_input(n, "color0", "color3", colour3(w.params, 0));
            add_input(n, "color82", "color3", colour3(w.params, 1));
            add_input(n, "color90", "color3", "1.0, 1.0, 1.0");
            add_input(n, "exponent", "float", "5.0");
            add_roughness(n);
            break;
        }
        case MaterialxForm::conductor_bsdf: {
            pugi::xml_node n = append_bsdf(root, "conductor_bsdf", bsdf);
            add_input(n, "ior", "color3", colour3(w.params, 0));
            add_input(n, "extinction", "color3", colour3(w.params, 1));
            add_roughness(n);
            break;
        }
        case MaterialxForm::artistic_ior: {
            const std::string ior = stem + "_artistic_ior";
            pugi::xml_node a = root.append_child("artistic_ior");
            a.append_attribute("name") = ior.c_str();
            a.append_attribute("type") = "multioutput";
            add_input(a, "reflectivity", "color3", colour3(w.params, 0));
            add_input(a, "edge_color", "color3", colour3(w.params, 1));
            pugi::xml_node n = append_bsdf(root, "conductor_bsdf", bsdf);
            for (const char* output : {"ior", "extinction"}) {
                pugi::xml_node in = n.append_child("input");
                in.append_attribute("name") = output;
                in.append_attribute("type") = "color3";
                in.append_attribute("nodename") = ior.c_str();
                in.append_attribute("output") = output;
            }
            add_roughness(n);
            break;
        }
    }
    std::string top = bsdf;
    if (layers && layers->coat) {
        // A smooth clear coat: a dielectric_bsdf reflecting (scatter_mode R) layered over the metal, as MaterialX's
        // PBR library (and its open_pbr_surface graph) layers a coat.
        const std::string coat = stem + "_coat_bsdf";
        pugi::xml_node c = append_bsdf(root, "dielectric_bsdf", coat);
        add_input(c, "weight", "float", "1.0");
        add_input(c, "tint", "color3", "1.0, 1.0, 1.0");
        add_input(c, "ior", "float", number(layers->coat_ior));
        add_input(c, "roughness", "vector2", "0.0, 0.0");
        add_input(c, "scatter_mode", "string", "R");
        top = stem + "_coated_bsdf";
        pugi::xml_node l = append_bsdf(root, "layer", top);
        const auto connect = [&l](const char* input, const std::string& node) {
            pugi::xml_node in = l.append_child("input");
            in.append_attribute("name") = input;
            in.append_attribute("type") = "BSDF";
            in.append_attribute("nodename") = node.c_str();
        };
        connect("top", coat);
        connect("base", bsdf);
    }
    add_surface_material(root, stem, top, true, provenance);
    return xml_text(doc);
}

}  // namespace

pugi::xml_node begin_materialx(pugi::xml_document& doc, const std::string& comment, const ExportContext& context) {
    pugi::xml_node decl = doc.append_child(pugi::node_declaration);
    decl.append_attribute("version") = "1.0";
    doc.append_child(pugi::node_comment).set_value(("\n" + no_double_hyphen(comment)).c_str());
    pugi::xml_node root = doc.append_child("materialx");
    root.append_attribute("version") = "1.39";
    if (!context.materialx_colorspace.empty())
        root.append_attribute("colorspace") = context.materialx_colorspace.c_str();
    return root;
}

void add_input(pugi::xml_node node, const char* name, const char* type, const std::string& value) {
    pugi::xml_node in = node.append_child("input");
    in.append_attribute("name") = name;
    in.append_attribute("type") = type;
    in.append_attribute("value") = value.c_str();
}

void add_surface_material(pugi::xml_node root, const std::string& stem, const std::string& shader, bool is_bsdf,
                          const std::string& doc) {
    std::string surface = shader;
    if (is_bsdf) {
        surface = stem + "_surface";
        pugi::xml_node s = root.append_child("surface");
        s.append_attribute("name") = surface.c_str();
        s.append_attribute("type") = "surfaceshader";
        pugi::xml_node in = s.append_child("input");
        in.append_attribute("name") = "bsdf";
        in.append_attribute("type") = "BSDF";
        in.append_attribute("nodename") = shader.c_str();
    }
    pugi::xml_node m = root.append_child("surfacematerial");
    m.append_attribute("name") = (stem + "_material").c_str();
    m.append_attribute("type") = "material";
    std::string text = doc;
    while (!text.empty() && text.back() == '\n') text.pop_back();
    m.append_attribute("doc") = text.c_str();
    pugi::xml_node in = m.append_child("input");
    in.append_attribute("name") = "surfaceshader";
    in.append_attribute("type") = "surfaceshader";
    in.append_attribute("nodename") = surface.c_str();
}

std::string xml_text(const pugi::xml_document& doc) {
    std::ostringstream s;
    doc.save(s, "  ", pugi::format_default, pugi::encoding_utf8);
    return s.str();
}

std::vector<ExportFile> export_mtlx(const std::vector<MaterialExport>& materials, const ExportContext& context) {
    std::vector<ExportFile> files;
    for (const MaterialExport& m : materials)
        for (std::size_t i = 0; i < m.models.size(); ++i) {
            std::vector<ColourOutOfRange> outside;
            std::string text = document(m, i, context, outside);
            files.push_back(
                {"mtlx/" + file_stem(context.request.id_prefix, m.fit->material.id, m.models[i].written.model->id()) +
                     ".mtlx",
                 std::move(text), std::move(outside)});
        }
    return files;
}

ConsumerCurve materialx_curve(const MaterialExport& material, const ModelExport& model, GamutPolicy) {
    std::string note;
    WrittenParameters w = materialx_parameters(material, model, note);
    std::string curve;
    switch (model.written.model->materialx_form()) {
        case MaterialxForm::generalized_schlick:
            curve = "generalized_schlick_bsdf (color0 = F0, color82 = tint, exponent 5)";
            break;
        case MaterialxForm::stand_in:
            curve = "generalized_schlick_bsdf of the stand-in " + std::string(w.model->id()) + " (" +
                    std::string(model.written.model->id()) + " has no MaterialX form)";
            break;
        case MaterialxForm::artistic_ior:
            curve = "artistic_ior feeding conductor_bsdf (reflectivity clamped to 0.99 by MaterialX)";
            break;
        case MaterialxForm::conductor_bsdf: curve = "conductor_bsdf (ior = n, extinction = k)"; break;
    }
    return {ExportFormat::mtlx, curve, std::move(w), ""};
}

}  // namespace metalfit::detail
