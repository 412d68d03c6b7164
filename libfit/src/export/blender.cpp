// Blender export: per material and model a Python script that builds the material in Blender, choosing by
// bpy.app.version at run time what that Blender's nodes can express (docs/export.md, Blender):
// - Blender >= 4.3: a Metallic BSDF (ShaderNodeBsdfMetallic, added in 4.3), in Physical Conductor mode with IOR = n
//   and Extinction = k for the n, k models (conductor-rgb; gulbrandsen through its r, g -> n, k mapping), in F82 Tint
//   mode with Base Color = F0 and Edge Tint = the tint for the F82-tint curves, and for the other models (and n, k
//   beyond the sockets' [0, 100]) the material's f82-tint parameters (the stand-in, said in the file);
// - Blender 4.0 - 4.2: the Principled BSDF with Metallic 1, Base Color = F0 and Specular Tint = the F82 tint (the
//   4.0 Principled BSDF's metal is the F82-tint model), the same F0 and tint as the F82 Tint mode above;
// - Blender < 4.0: the Principled BSDF with Metallic 1, Base Color = F(mu = 1) of the written curve and Specular 1:
//   no tint; the curve left is Schlick's from F0, whose error the header gives.
#include <complex>

#include "export/export_formats.hpp"
#include "libfit/base/names.hpp"
#include "libfit/fit/metrics.hpp"
#include "libfit/models/gulbrandsen/gulbrandsen.hpp"
#include "libfit/models/registry.hpp"
#include "libfit/models/schlick/schlick.hpp"

namespace metalfit::detail {

namespace {

// The Metallic BSDF's IOR and Extinction sockets hold [0, 100] (node_shader_bsdf_metallic.cc: .min(0).max(100));
// Blender clamps a value set beyond.
constexpr double kSocketMax = 100.0;

std::string tuple(const RGB& v) { return "(" + number(v.r) + ", " + number(v.g) + ", " + number(v.b) + ")"; }

std::string worst_rel_rms(const WrittenParameters& w) { return number(worst_channel(w.metrics.rel_rms)); }

// n and k of an n, k model's written parameters: conductor-rgb's own, gulbrandsen's through Gulbrandsen::to_nk.
std::optional<std::pair<RGB, RGB>> index_of(const WrittenParameters& written) {
    const MaterialxForm form = written.model->materialx_form();
    if (form == MaterialxForm::conductor_bsdf)
        return std::pair{written.params.parameter(0), written.params.parameter(1)};
    if (form != MaterialxForm::artistic_ior) return std::nullopt;
    RGB n, k;
    for (int c = 0; c < 3; ++c) {
        const std::complex<double> nk = models::Gulbrandsen::to_nk(written.params[c][0], written.params[c][1]);
        n[c] = nk.real();
        k[c] = nk.imag();
    }
    return std::pair{n, k};
}

bool in_socket_range(const RGB& v) {
    for (int c = 0; c < 3; ++c)
        if (!(v[c] >= 0.0 && v[c] <= kSocketMax)) return false;
    return true;
}

// What Blender >= 4.3's Metallic BSDF is given: an n, k curve whose n, k the sockets hold in Physical Conductor
// mode, else the curve's F82-tint form (or the stand-in, the material's f82-tint fit) in F82 Tint mode.
struct MetallicBsdfChoice {
    std::optional<std::pair<RGB, RGB>> nk;  // the written curve's n, k (n, k models)
    bool conductor = false;                 // Physical Conductor mode
    WrittenParameters f82;                  // the F82 Tint mode's values
    bool f82_is_stand_in = false;
};

MetallicBsdfChoice metallic_bsdf_choice(const MaterialExport& m, const ModelExport& e) {
    MetallicBsdfChoice choice;
    std::optional<WrittenParameters> f82 = as_f82_tint(e.written, *m.fit->reference);
    choice.f82_is_stand_in = !f82;
    choice.f82 = f82 ? *f82 : *e.stand_in;
    choice.nk = index_of(e.written);
    choice.conductor = choice.nk && in_socket_range(choice.nk->first) && in_socket_range(choice.nk->second);
    return choice;
}

}  // namespace

ConsumerCurve blender_curve(const MaterialExport& material, const ModelExport& model, GamutPolicy) {
    MetallicBsdfChoice choice = metallic_bsdf_choice(material, model);
    if (choice.conductor)
        return {ExportFormat::blender,
                "Blender >= 4.3's Metallic BSDF in Physical Conductor mode (IOR = n, Extinction = k), as Cycles "
                "evaluates it",
                model.written, ""};
    return {ExportFormat::blender,
            "Blender >= 4.3's Metallic BSDF in F82 Tint mode (Base Color = F0, Edge Tint = tint)" +
                std::string(choice.f82_is_stand_in ? " of the stand-in " + std::string(choice.f82.model->id()) : ""),
            std::move(choice.f82), ""};
}

std::vector<ExportFile> export_blender(const std::vector<MaterialExport>& materials, const ExportContext& context) {
    std::vector<ExportFile> files;
    const Model& schlick = model_of<models::Schlick>();
    for (const MaterialExport& m : materials)
        for (const ModelExport& e : m.models) {
            const std::string model_id(e.written.model->id());
            const std::string stem = file_stem(context.request.id_prefix, m.fit->material.id, model_id);
            const SampledReference& reference = *m.fit->reference;

            // Blender >= 4.3: Physical Conductor for an n, k curve whose n, k the sockets hold, else F82 Tint with
            // the F82-tint form (the curve itself, or the stand-in: the material's f82-tint fit).
            const MetallicBsdfChoice choice = metallic_bsdf_choice(m, e);
            const std::optional<WrittenParameters> f82 = choice.f82;
            const bool f82_is_stand_in = choice.f82_is_stand_in;
            const std::optional<std::pair<RGB, RGB>>& nk = choice.nk;
            const bool conductor = choice.conductor;

            // Blender < 4.0: Schlick from F0 = the written curve at normal incidence.
            const RGB f0 = e.written.model->evaluate(e.written.params, 1.0);
            WrittenParameters schlick_at_f0{
                &schlick, "F0 = " + model_id + "'s curve at mu = 1", ModelParameters({f0.r}, {f0.g}, {f0.b}), {}, {}};
            schlick_at_f0.metrics = compute_metrics(schlick, schlick_at_f0.params, reference);

            const WrittenParameters& header_values = conductor ? e.written : *f82;
            std::string note;
            const auto add = [&](const std::string& line) { note += (note.empty() ? "" : "\n") + line; };
            add("Blender: run this script in Blender (Scripting > Run Script, or blender --python " + stem +
                ".py); it makes the material and chooses by bpy.app.version what that Blender can express:");
            if (conductor)
                add("  Blender >= 4.3: Metallic BSDF, Physical Conductor: IOR = n, Extinction = k" +
                    std::string(e.written.model->materialx_form() == MaterialxForm::artistic_ior
                                    ? " (gulbrandsen's r, g mapped to n, k: the same curve)"
                                    : "") +
                    ", the figures below. Cycles evaluates the exact conductor Fresnel of these n, k; EEVEE does not: "
                    "it passes F(0 deg) and F(82 deg) of them into its F82-tint curve as Base Color and Edge Tint, "
                    "so for EEVEE use the f82-tint export of this material (F82 Tint mode, fitted over all angles)");
            else if (nk)
                add("  Blender >= 4.3: Metallic BSDF, F82 Tint: " + model_id +
                    "'s n, k lie beyond the Metallic BSDF's IOR and Extinction range [0, 100], so the f82-tint "
                    "parameters (" +
                    f82->origin + ") are written: " + model_id + "'s own worst-channel rel_rms would be " +
                    worst_rel_rms(e.written) + ", these parameters' is " + worst_rel_rms(*f82));
            else if (f82_is_stand_in)
                add("  Blender >= 4.3: Metallic BSDF, F82 Tint: " + model_id +
                    " is not an F82-tint curve: written as the f82-tint parameters (" + f82->origin + "); " + model_id +
                    "'s own worst-channel rel_rms would be " + worst_rel_rms(e.written) + ", these parameters' is " +
                    worst_rel_rms(*f82));
            else
                add("  Blender >= 4.3: Metallic BSDF, F82 Tint: Base Color = F0, Edge Tint = tint: the " + model_id +
                    " curve itself in Cycles and EEVEE, the figures below");
            add("  Blender 4.0 - 4.2 (no Metallic BSDF): Principled BSDF, Metallic 1, Base Color = F0, Specular Tint "
                "= the F82 tint" +
                (f82_is_stand_in ? " of the f82-tint parameters (worst-channel rel_rms " + worst_rel_rms(*f82) + ")"
                                 : std::string(": the same curve")));
            add("  Blender < 4.0 (no F82 tint): Principled BSDF, Metallic 1, Base Color = F0 = " + model_id +
                "'s curve at mu = 1, Specular 1 (EEVEE 3.x then blends F0 to 1 by Schlick's weight; Cycles 3.x by a "
                "normalised dielectric Fresnel of IOR 1.79): Schlick from F0, worst-channel rel_rms " +
                worst_rel_rms(schlick_at_f0) + " (R, G, B: " + number(schlick_at_f0.metrics.rel_rms[0]) + ", " +
                number(schlick_at_f0.metrics.rel_rms[1]) + ", " + number(schlick_at_f0.metrics.rel_rms[2]) + ")");
            add("Roughness = --roughness (perceptual, alpha = r^2, as in Blender). The Metallic BSDF clamps Base Color "
                "and Edge Tint to [0, 1]; a channel above 1 is flagged OUT OF RANGE below and on stderr.");
            if (context.materialx_colorspace != "lin_rec709")
                add("WARNING: colours are in " + context.record.space +
                    "; Blender reads node colours in its scene-linear working space (Linear Rec.709 in its default "
                    "configuration): convert them, or export with --space 'Linear Rec.709 (sRGB)'");

            static constexpr std::array<std::string_view, 2> kBlenderNames{"Base Color", "Edge Tint"};
            std::vector<ColourOutOfRange> outside =
                conductor ? std::vector<ColourOutOfRange>{} : colours_out_of_range(m, *f82, model_id, kBlenderNames);
            const RGB f82_f0 = f82->params.parameter(0);
            for (int c = 0; c < 3; ++c)  // Blender < 4.0's Base Color, where it is not the F82 form's F0 checked above
                if (!(f0[c] >= 0.0 && f0[c] <= 1.0) && (conductor || f0[c] != f82_f0[c]))
                    outside.push_back({m.fit->material.id, model_id, "Base Color (Blender < 4.0)", c, f0[c]});

            std::string py = comment_header(m, header_values, context, "# ", note);
            py += "\nimport bpy\n\n";
            py += "MATERIAL_NAME = " + python_string_expression(m.fit->material.name + " (metalfit " + model_id + ")") +
                  "\n";
            py += "ROUGHNESS = " + number(context.request.roughness) + "\n";
            py += "# Blender >= 4.3, Metallic BSDF: " +
                  std::string(conductor ? "'PHYSICAL_CONDUCTOR' (IOR, EXTINCTION)" : "'F82' (F0, EDGE_TINT)") + "\n";
            py += "FRESNEL_TYPE = '" + std::string(conductor ? "PHYSICAL_CONDUCTOR" : "F82") + "'\n";
            if (conductor) {
                py += "IOR = " + tuple(nk->first) + "\n";
                py += "EXTINCTION = " + tuple(nk->second) + "\n";
            }
            py += "# The F82-tint form" +
                  std::string(f82_is_stand_in || conductor ? " (the f82-tint parameters)" : "") +
                  ": F0 and tint (Blender 4.0 - 4.2; and >= 4.3 in F82 mode)\n";
            py += "F0 = " + tuple(f82->params.parameter(0)) + "\n";
            py += "EDGE_TINT = " + tuple(f82->params.parameter(1)) + "\n";
            py += "# Blender < 4.0: Base Color = the curve at normal incidence\n";
            py += "BASE_COLOR_BEFORE_4_0 = " + tuple(f0) + "\n";
            py += R"(

def build_material(name=MATERIAL_NAME):
    """Makes the material (a new one each call; Blender appends .001 to a name in use) and returns it."""
    material = bpy.data.materials.new(name)
    material.use_nodes = True
    nodes = material.node_tree.nodes
    nodes.clear()
    output = nodes.new('ShaderNodeOutputMaterial')
    output.location = (300, 0)
    if bpy.app.version >= (4, 3, 0):
        bsdf = nodes.new('ShaderNodeBsdfMetallic')
        bsdf.distribution = 'MULTI_GGX'
        bsdf.fresnel_type = FRESNEL_TYPE
        if FRESNEL_TYPE == 'PHYSICAL_CONDUCTOR':
            bsdf.inputs['IOR'].default_value = IOR
            bsdf.inputs['Extinction'].default_value = EXTINCTION
        else:
            bsdf.inputs['Base Color'].default_value = F0 + (1.0,)
            bsdf.inputs['Edge Tint'].default_value = EDGE_TINT + (1.0,)
    else:
        bsdf = nodes.new('ShaderNodeBsdfPrincipled')
        bsdf.inputs['Metallic'].default_value = 1.0
        if bpy.app.version >= (4, 0, 0):
            bsdf.inputs['Base Color'].default_value = F0 + (1.0,)
            bsdf.inputs['Specular Tint'].default_value = EDGE_TINT + (1.0,)
        else:
            bsdf.inputs['Base Color'].default_value = BASE_COLOR_BEFORE_4_0 + (1.0,)
            bsdf.inputs['Specular'].default_value = 1.0
    bsdf.inputs['Roughness'].default_value = ROUGHNESS
    material.node_tree.links.new(bsdf.outputs['BSDF'], output.inputs['Surface'])
)";
            py += "    material['metalfit'] = {'material': " + python_string_expression(m.fit->material.id) +
                  ", 'model': '" + model_id + "', 'color_space': " + python_string_expression(context.record.space) +
                  ", 'file': '" + stem + ".py'}\n";
            py += R"(    return material


material = build_material()
)";
            files.push_back({"blender/" + stem + ".py", py, outside});
        }
    return files;
}

}  // namespace metalfit::detail
