// Shared by the exporters (export_*.cpp): what one material's export holds, names, number formatting and the
// comment header every text export starts with.
#pragma once

#include <memory>
#include <optional>
#include <span>
#include <string>
#include <vector>

#include <pugixml.hpp>

#include "libfit/export/consumer_curve.hpp"
#include "libfit/export/export.hpp"
#include "libfit/io/layer_stack.hpp"

namespace metalfit::detail {

// One exported model of one material.
struct ModelExport {
    WrittenParameters written;
    // For MaterialX / OpenPBR where the model has no native form: the stand-in's written parameters.
    std::optional<WrittenParameters> stand_in;
};

struct MaterialExport {
    const MaterialFit* fit = nullptr;
    std::vector<ModelExport> models;
    // A layered material in a format that layers a coat or film itself: the export of its bare metal (the same
    // models, in the same order), whose constants are the base under the format's own layers; null otherwise.
    std::shared_ptr<const MaterialExport> bare_metal = nullptr;
};

// What a layered format writes for one material: `bare_metal` when it has one, else the material itself (a bare
// metal, or a layered one in a request without those formats).
inline const MaterialExport& base_export(const MaterialExport& m) { return m.bare_metal ? *m.bare_metal : m; }

struct ExportContext {
    FitRecordContext record;
    ExportRequest request;
    std::string materialx_colorspace;  // MaterialX's name of record.space, empty when it has none
};

// "metalfit", "Au", "f82-tint" → "metalfit_au_f82_tint" (lower case, every other character '_'): the one name every
// per-material identifier is made of (file stems, function names, namespaces, MaterialX / glTF names).
std::string file_stem(std::string_view id_prefix, const std::string& material_id, std::string_view model_id);
// The same in upper case ("METALFIT_AU_F82_TINT"): shader constants and include guards.
std::string constant_stem(std::string_view id_prefix, const std::string& material_id, std::string_view model_id);
// "metalfit" → "cpp/metalfit_materials.hpp", and its namespace "metalfit_materials".
std::string cpp_index_name(std::string_view id_prefix);
std::string cpp_index_path(std::string_view id_prefix);

// Shortest text that reads back as the same double ("%.17g"), always with a '.' or an exponent.
std::string number(double v);
// The float nearest v as the shortest text that reads back as that float (at most 9 significant digits): the
// shader constants, which GLSL and HLSL store as 32-bit floats.
std::string shader_number(double v);
// "a, b, c" of channel values of parameter `index`: as doubles (number), or as floats (shader_number).
std::string channel_list(const ModelParameters& params, std::size_t index);
std::string shader_channel_list(const ModelParameters& params, std::size_t index);

// The comment header of a text export, one line per entry, each prefixed with `prefix` ("// "): material, data
// source, colour space, model, where the parameters come from, gamut notes, error figures, metalfit version.
// `base_of_layers`: the written parameters are the bare metal's, under the format's own coat / thin film (the
// stack line says so, and the error figures are against the bare metal's curve).
std::string comment_header(const MaterialExport& material, const WrittenParameters& written,
                           const ExportContext& context, std::string_view prefix, std::string_view extra = {},
                           bool base_of_layers = false);

// The colour parameters of `written` (ParameterKind::colour) with a channel outside [0, 1], as written; `names`
// replaces the model's parameter names where the format writes them under its own (OpenPBR base_color, …).
// `model` is the exported model's id (the stand-in's values are written for it by some formats).
std::vector<ColourOutOfRange> colours_out_of_range(const MaterialExport& material, const WrittenParameters& written,
                                                   std::string_view model,
                                                   std::span<const std::string_view> names = {});

// One line (and one per parameter at its fit bound) saying whether `written` survives half precision (|x| <= 65504):
// its constants, and what a conductor (k², 4n²k²) or Gulbrandsen's r, g → n, k compute from them.
std::string half_precision_note(const WrittenParameters& written, std::string_view prefix);

// How a shading language spells the constants of export_glsl / export_hlsl.
struct ShaderSyntax {
    std::string_view constant;     // "const vec3" | "static const float3"
    std::string_view vector;       // "vec3" | "float3"
    std::string_view models_file;  // the shared file of model functions
    std::string_view language;     // what the files need: "GLSL >= 1.30 …" | "HLSL …"
    std::string_view extension;    // "GLSL" | "HLSL": include guards METALFIT_<MATERIAL>_<MODEL>_<extension>
    // MSL: the function copies each constant into a local of the parameter's name before the call (the models take
    // `thread const float3&`, which a `constant` object does not bind to).
    bool copy_to_locals;
};
// The constants of one material and model, and `<vector> metalfit_<material>_<model>(float mu)` calling the model.
std::string shader_constants(const MaterialExport& material, const ModelExport& model, const ExportContext& context,
                             const ShaderSyntax& syntax);

// The shared files of model functions, for a list of models (an export's, or the union when merging).
std::string glsl_models_file(const std::vector<const Model*>& models);
std::string hlsl_models_file(const std::vector<const Model*>& models);
std::string cpp_models_file(const std::vector<const Model*>& models);
std::string msl_models_file(const std::vector<const Model*>& models);
std::string wgsl_models_file(const std::vector<const Model*>& models);

// cpp/metalfit_materials.hpp: one #include and one table row per material and model.
struct CppIndexEntry {
    std::string include;  // #include "<stem>.hpp"
    std::string row;      // {"Au", "f82-tint", &<stem>::evaluate, …},
};
std::string cpp_materials_index(const std::vector<CppIndexEntry>& entries, std::string_view id_prefix);
// Its parts, for ExportStream: the head, the includes (one line each), the middle, the rows (one line each), the tail.
std::string cpp_materials_index_head();
std::string cpp_materials_index_middle(std::string_view id_prefix, std::size_t count);
std::string cpp_materials_index_tail(std::string_view id_prefix);
// The entries of a file cpp_materials_index wrote; std::invalid_argument when it is not one.
std::vector<CppIndexEntry> parse_cpp_materials_index(std::string_view text);

// metalfit_export.json: the record already in a folder with the materials and models of `mine` added (replacing
// the same material and model). std::invalid_argument saying why when the two cannot be one record (other colour
// space, illuminant, settings or version; the same material from other data).
std::string merge_json_record(const std::string& existing, const std::string& mine);

std::vector<ExportFile> export_json(const std::vector<MaterialExport>& materials, const ExportContext& context);
std::vector<ExportFile> export_glsl(const std::vector<MaterialExport>& materials, const ExportContext& context);
std::vector<ExportFile> export_hlsl(const std::vector<MaterialExport>& materials, const ExportContext& context);
std::vector<ExportFile> export_cpp(const std::vector<MaterialExport>& materials, const ExportContext& context);
std::vector<ExportFile> export_mtlx(const std::vector<MaterialExport>& materials, const ExportContext& context);
std::vector<ExportFile> export_openpbr(const std::vector<MaterialExport>& materials, const ExportContext& context);
std::vector<ExportFile> export_gltf(const std::vector<MaterialExport>& materials, const ExportContext& context);
std::vector<ExportFile> export_msl(const std::vector<MaterialExport>& materials, const ExportContext& context);
std::vector<ExportFile> export_wgsl(const std::vector<MaterialExport>& materials, const ExportContext& context);
std::vector<ExportFile> export_blender(const std::vector<MaterialExport>& materials, const ExportContext& context);

// The written parameters of every requested model of one fit (and the stand-in's where a format needs it); the
// fit holds models_to_fit(request). No bare-metal export is attached (export_files does that).
MaterialExport material_export(const MaterialFit& fit, const ExportRequest& request);

// Every file of an export, one list per format of the request (in its order), the record's out_of_range and
// consumers filled in: what export_files joins (and checks for files two materials would share), and what
// ExportStream makes for one material at a time.
std::vector<std::vector<ExportFile>> export_files_by_format(const std::vector<MaterialFit>& fits,
                                                            const FitRecordContext& context,
                                                            const ExportRequest& request,
                                                            const std::string& materialx_space);

// What each format's consumer evaluates for one exported model (consumer_curve.hpp; the registry's `consumer_curve`):
// the model itself (JSON, GLSL, HLSL, C++), MaterialX's node, OpenPBR's F82-tint metal, Schlick from glTF's
// baseColorFactor. `material` is bare, or layered in a format that evaluates the stack's fitted curve.
ConsumerCurve own_model_curve(const MaterialExport& material, const ModelExport& model, GamutPolicy gamut);
ConsumerCurve materialx_curve(const MaterialExport& material, const ModelExport& model, GamutPolicy gamut);
ConsumerCurve openpbr_curve(const MaterialExport& material, const ModelExport& model, GamutPolicy gamut);
ConsumerCurve gltf_curve(const MaterialExport& material, const ModelExport& model, GamutPolicy gamut);
ConsumerCurve blender_curve(const MaterialExport& material, const ModelExport& model, GamutPolicy gamut);
// The curve of each format of `request` for one model of `material` (a layered material's formats that layer
// themselves: not evaluated).
std::vector<ConsumerCurve> consumer_curves(const MaterialExport& material, const ModelExport& model,
                                           const ExportRequest& request);

// glTF's baseColorFactor of a written model: its curve at normal incidence (F0 = F(mu = 1)), with a channel outside
// [0, 1] clipped, or the colour scaled by 1 / max under --gamut scale (glTF holds [0, 1] only); `adjustment` says
// what was done, empty when F0 was in [0, 1].
struct GltfBaseColor {
    RGB f0;
    RGB factor;
    std::string adjustment;
};
GltfBaseColor gltf_base_color(const WrittenParameters& written, GamutPolicy gamut);

// MaterialX documents (export_mtlx.cpp, used by export_openpbr.cpp too): <materialx version="1.39"> after a comment
// (the header), with colorspace when MaterialX has a name for the curves' space (context.materialx_colorspace).
pugi::xml_node begin_materialx(pugi::xml_document& doc, const std::string& comment, const ExportContext& context);
void add_input(pugi::xml_node node, const char* name, const char* type, const std::string& value);
// <surface> around the BSDF node `bsdf` (unless it already is a surfaceshader) and <surfacematerial> around that,
// whose `doc` attribute holds `doc` (the comment header's lines: MaterialX keeps doc through a read and write, where
// it drops comments).
void add_surface_material(pugi::xml_node root, const std::string& stem, const std::string& shader, bool is_bsdf,
                          const std::string& doc);
std::string xml_text(const pugi::xml_document& doc);

// The header line of a MaterialX document whose space MaterialX cannot name (export_warnings says the same on stderr).
std::string untagged_materialx_warning(const std::string& ocio_space);

// A layered material as the formats with their own coat and thin film take it (layered.cpp; docs/export.md, Layered
// exports): each layer's one index at kLayerIndexWavelengthNm and its thickness, and what the format cannot express.
struct LayeredParameters {
    bool coat = false;
    double coat_ior = 1.0;           // the coat's n at 550 nm
    bool coat_absorbs = false;       // a coat given a thickness whose table has k > 0 somewhere in the visible
    bool film = false;               // a thin film (thickness and index below)
    double film_thickness_nm = 0.0;  // MaterialX thinfilm_thickness (nanometres), glTF iridescenceThickness*
    double film_thickness_um = 0.0;  // OpenPBR thin_film_thickness (micrometres)
    double film_ior = 1.0;           // the film's n at 550 nm
    LayerIndexSummary coat_index = {};
    LayerIndexSummary film_index = {};
};
// Null when `material` has no layers.
std::optional<LayeredParameters> layered_parameters(const Material& material);
// One line per thing `format` (openpbr, mtlx or gltf) cannot carry of the stack or takes as an approximation: the
// indices as one number at 550 nm of a dispersive layer, an absorbing film's k, an absorbing coat, glTF's clearcoat
// IOR fixed at 1.5; and a first line saying how the stack is written. For the comment headers and the JSON `layers`.
std::vector<std::string> layered_notes(const LayeredParameters& layers, ExportFormat format);

// F0 and tint of the F82-tint form that evaluates the same curve as `written` (schlick: tint 1; lazanyi: F0 of n, k,
// tint 1; f82-tint: itself), or nothing when the model has no F82-tint form (then the stand-in is used).
std::optional<WrittenParameters> as_f82_tint(const WrittenParameters& written, const SampledReference& reference);

}  // namespace metalfit::detail
