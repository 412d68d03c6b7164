// MaterialX 1.39 export (pugixml): f82-tint, schlick and lazanyi as generalized_schlick_bsdf (color0 = F0,
// color82 = tint, exponent 5: the same curve), conductor-rgb as conductor_bsdf (ior = n, extinction = k),
// gulbrandsen as artistic_ior feeding conductor_bsdf, and lazanyi-comp, which MaterialX cannot express, as its
// closest expressible stand-in (the f82-tint fit). Each BSDF is wrapped in surface + surfacematerial.
#include <algorithm>
#include <sstream>

#include "export/export_formats.hpp"

namespace metalfit::detail {

namespace {

// MaterialX's artistic_ior clamps reflectivity to [0, 0.99] in every shading language it generates.
constexpr double kArtisticIorMaxReflectivity = 0.99;

std::string no_double_hyphen(std::string s) {  // "--" may not appear in an XML comment
    for (std::size_t p = s.find("--"); p != std::string::npos; p = s.find("--", p)) s.replace(p, 2, "- -");
    return s;
}

std::string colour3(const RgbParameters& params, std::size_t index) { return channel_list(params, index); }

std::string document(const MaterialExport& m, const ModelExport& e, const ExportContext& context) {
    const std::string& ocio_space = context.record.space;
    const std::string stem = file_stem(m.fit->material.id, e.written.model->id());
    const std::string_view id = e.written.model->id();
    WrittenParameters w = e.written;
    std::string extra;
    if (id == "lazanyi-comp") {
        w = *e.stand_in;
        extra = "lazanyi-comp has no MaterialX form (a BSDF's Fresnel cannot take mu (1 - mu)^alpha): written as its closest\n"
                "expressible fit, f82-tint in generalized_schlick_bsdf (exponent 5); lazanyi-comp's own worst-channel rel_rms\n"
                "would be " + number(worst_channel(e.written.metrics.rel_rms)) + ", this stand-in's is " +
                number(worst_channel(w.metrics.rel_rms)) + "; the figures below are the stand-in's.";
    } else if (id == "gulbrandsen") {
        bool clamped = false;
        for (int c = 0; c < 3; ++c)
            if (w.params[c][0] > kArtisticIorMaxReflectivity) w.params[c][0] = kArtisticIorMaxReflectivity, clamped = true;
        if (clamped) {
            w.metrics = compute_metrics(*w.model, w.params, *m.fit->reference);
            w.gamut.push_back("r above 0.99, which MaterialX's artistic_ior clamps to 0.99: written as 0.99");
        }
    } else if (id != "conductor-rgb") {
        w = *as_f82_tint(e.written, *m.fit->reference);
    }
    if (ocio_space.empty() || materialx_colorspace(ocio_space).empty())
        extra += std::string(extra.empty() ? "" : "\n") + "colours are in " + ocio_space + ", which has no MaterialX colorspace name: none is set";
    pugi::xml_document doc;
    pugi::xml_node root = begin_materialx(doc, comment_header(m, w, context, "  ", extra), ocio_space);
    const std::string bsdf = stem + "_bsdf";
    const std::string_view written_id = w.model->id();
    if (written_id == "f82-tint") {
        pugi::xml_node n = root.append_child("generalized_schlick_bsdf");
        n.append_attribute("name") = bsdf.c_str();
        n.append_attribute("type") = "BSDF";
        add_input(n, "color0", "color3", colour3(w.params, 0));
        add_input(n, "color82", "color3", colour3(w.params, 1));
        add_input(n, "color90", "color3", "1.0, 1.0, 1.0");
        add_input(n, "exponent", "float", "5.0");
    } else if (written_id == "conductor-rgb") {
        pugi::xml_node n = root.append_child("conductor_bsdf");
        n.append_attribute("name") = bsdf.c_str();
        n.append_attribute("type") = "BSDF";
        add_input(n, "ior", "color3", colour3(w.params, 0));
        add_input(n, "extinction", "color3", colour3(w.params, 1));
    } else {  // gulbrandsen
        const std::string ior = stem + "_artistic_ior";
        pugi::xml_node a = root.append_child("artistic_ior");
        a.append_attribute("name") = ior.c_str();
        a.append_attribute("type") = "multioutput";
        add_input(a, "reflectivity", "color3", colour3(w.params, 0));
        add_input(a, "edge_color", "color3", colour3(w.params, 1));
        pugi::xml_node n = root.append_child("conductor_bsdf");
        n.append_attribute("name") = bsdf.c_str();
        n.append_attribute("type") = "BSDF";
        for (const char* output : {"ior", "extinction"}) {
            pugi::xml_node in = n.append_child("input");
            in.append_attribute("name") = output;
            in.append_attribute("type") = "color3";
            in.append_attribute("nodename") = ior.c_str();
            in.append_attribute("output") = output;
        }
    }
    add_surface_material(root, stem, bsdf, true);
    return xml_text(doc);
}

}  // namespace

pugi::xml_node begin_materialx(pugi::xml_document& doc, const std::string& comment, const std::string& ocio_space) {
    pugi::xml_node decl = doc.append_child(pugi::node_declaration);
    decl.append_attribute("version") = "1.0";
    doc.append_child(pugi::node_comment).set_value(("\n" + no_double_hyphen(comment)).c_str());
    pugi::xml_node root = doc.append_child("materialx");
    root.append_attribute("version") = "1.39";
    if (const std::string cs = materialx_colorspace(ocio_space); !cs.empty()) root.append_attribute("colorspace") = cs.c_str();
    return root;
}

void add_input(pugi::xml_node node, const char* name, const char* type, const std::string& value) {
    pugi::xml_node in = node.append_child("input");
    in.append_attribute("name") = name;
    in.append_attribute("type") = type;
    in.append_attribute("value") = value.c_str();
}

void add_surface_material(pugi::xml_node root, const std::string& stem, const std::string& shader, bool is_bsdf) {
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
        for (const ModelExport& e : m.models)
            files.push_back({"mtlx/" + file_stem(m.fit->material.id, e.written.model->id()) + ".mtlx", document(m, e, context)});
    return files;
}

}  // namespace metalfit::detail
