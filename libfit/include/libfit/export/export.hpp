// Exports: fitted (or closed-form) model parameters written as files that shaders and material systems consume
// (docs/export.md). The library does all the work; `metalfit export` only parses arguments and calls it.
#pragma once

#include <filesystem>
#include <string>
#include <string_view>
#include <vector>

#include "libfit/base/enum_names.hpp"
#include "libfit/export/roughness.hpp"
#include "libfit/fit/fit.hpp"
#include "libfit/fit/fit_batch.hpp"
#include "libfit/fit/fit_record.hpp"
#include "libfit/fit/metrics.hpp"
#include "libfit/fit/parameter_source.hpp"
#include "libfit/models/model.hpp"

namespace metalfit {

// The formats, in the order `--format all` writes them (each format's writer, files and rules: the private
// format registry, src/export/format_registry.hpp).
enum class ExportFormat { json, glsl, hlsl, mtlx, openpbr, cpp, gltf, blender, msl, wgsl };
inline constexpr EnumNames kExportFormatNames{
    "export format", KnownNamesWording::known,
    std::array{EnumName<ExportFormat>{ExportFormat::json, "json"}, EnumName<ExportFormat>{ExportFormat::glsl, "glsl"},
               EnumName<ExportFormat>{ExportFormat::hlsl, "hlsl"}, EnumName<ExportFormat>{ExportFormat::mtlx, "mtlx"},
               EnumName<ExportFormat>{ExportFormat::openpbr, "openpbr"},
               EnumName<ExportFormat>{ExportFormat::cpp, "cpp"}, EnumName<ExportFormat>{ExportFormat::gltf, "gltf"},
               EnumName<ExportFormat>{ExportFormat::blender, "blender"},

               EnumName<ExportFormat>{ExportFormat::msl, "msl"}, EnumName<ExportFormat>{ExportFormat::wgsl, "wgsl"}}};
std::string to_string(ExportFormat format);

// What happens to colour parameters (F0, tint, r, g) outside [0, 1]: written as they are and flagged, clipped to
// [0, 1], or the whole colour scaled by 1 / max (Adobe's rule). n, k, a and α are not colours and are never changed.
enum class GamutPolicy { keep, clip, scale };
inline constexpr EnumNames kGamutPolicyNames{"gamut policy", KnownNamesWording::alternatives,
                                             std::array{EnumName<GamutPolicy>{GamutPolicy::keep, "keep"},
                                                        EnumName<GamutPolicy>{GamutPolicy::clip, "clip"},
                                                        EnumName<GamutPolicy>{GamutPolicy::scale, "scale"}}};
GamutPolicy parse_gamut_policy(const std::string& text);  // "keep" | "clip" | "scale", else UsageError
std::string to_string(GamutPolicy policy);

// The parameters of one model exactly as they are written, and the error figures of those values (recomputed with
// compute_metrics on the material's sampled reference, so they describe what a consumer evaluates).
struct WrittenParameters {
    const Model* model = nullptr;
    std::string origin;  // "fit" or "closed r1-r82"
    ModelParameters params;
    Metrics metrics;
    std::vector<std::string> gamut;  // one note per out-of-gamut colour parameter: what was done to it
};

// Chooses the fit or the best closed form of `result`, applies the gamut policy and recomputes the metrics.
// Throws UsageError naming the material and the reasons when closed parameters are asked and none is defined.
WrittenParameters written_parameters(const ModelResult& result, const SampledReference& reference,
                                     ParameterSource source, GamutPolicy gamut, const std::string& material_id);

// The prefix of every per-material identifier an export writes (file stems, shader functions and constants, include
// guards, C++ namespaces and the index, MaterialX / OpenPBR / glTF names): `<prefix>_<material>_<model>`. The shared
// model functions (metalfit_f82_tint, …) keep their names. Written in metalfit_export.json only when not the default.
inline constexpr const char* kDefaultIdPrefix = "metalfit";
// Why `text` cannot be an id prefix, or empty when it can: it must match [a-z][a-z0-9_]{0,30}, have no "__", not
// end in '_', not be "gl" (GLSL reserves gl_…) and not be a C++, GLSL or HLSL keyword.
std::string id_prefix_problem(std::string_view text);

struct ExportRequest {
    std::vector<ExportFormat> formats;
    std::vector<const Model*> models;  // the models exported, in order
    ParameterSource source = ParameterSource::fit;
    GamutPolicy gamut = GamutPolicy::keep;
    double roughness = kDefaultRoughness;
    std::string id_prefix = kDefaultIdPrefix;
};

// The model the MaterialX and OpenPBR exports use where a model has no native equivalent (lazanyi-comp in MaterialX;
// every n, k model in OpenPBR): f82-tint, the closest model MaterialX's generalized_schlick_bsdf and OpenPBR evaluate.
const Model& expressible_stand_in();

// The models to fit for a request: the requested ones, plus the stand-in when a format needs it.
std::vector<const Model*> models_to_fit(const ExportRequest& request);

// Whether the request writes a format that expresses a layered material's coat and thin film with its own
// parameters over the bare metal's constants (OpenPBR coat_* / thin_film_*, MaterialX layer + dielectric_bsdf /
// thinfilm_*, glTF KHR_materials_clearcoat / KHR_materials_iridescence): those need the bare metal's fit.
bool needs_bare_metal_fits(const ExportRequest& request);
// For every layered material of `fits` (material.layers not empty): fits its metal alone (the same material, data
// and request, layers removed) and sets `bare_metal`. Bare materials are left as they are.
void attach_bare_metal_fits(std::vector<MaterialFit>& fits, const BatchColour& colour,
                            const MaterialFitRequest& request, int jobs);

// A colour channel a file writes outside [0, 1] (F0, tint, r, g, OpenPBR's base_color / specular_color, …): a
// consumer clips it, or renders more light than arrives. `parameter` is the name the file writes it under.
struct ColourOutOfRange {
    std::string material;   // material id
    std::string model;      // model id of the export (the stand-in's values when the file writes the stand-in)
    std::string parameter;  // "F0", "tint", "specular_color", …
    int channel = 0;        // 0, 1, 2: red, green, blue
    double value = 0;
};

// One output file, its path relative to the output directory, and the colours it writes outside [0, 1].
struct ExportFile {
    std::filesystem::path path;
    std::string contents;
    std::vector<ColourOutOfRange> out_of_range = {};
};

// One line per colour channel an export writes outside [0, 1], for stderr:
// "export: openpbr/metalfit_cs_f82_tint.json: specular_color red = 1.37 outside [0, 1] (Cs, f82-tint)".
std::vector<std::string> out_of_range_lines(const std::vector<ExportFile>& files);

// Every file of an export (layout in docs/export.md). `fits` must hold the models of models_to_fit(request);
// `materialx_space` is materialx_colorspace(context.config, context.space), resolved once by the caller (it reads
// the OCIO config) and given to export_warnings too.
std::vector<ExportFile> export_files(const std::vector<MaterialFit>& fits, const FitRecordContext& context,
                                     const ExportRequest& request, const std::string& materialx_space);

// MaterialX's name of the OCIO colour space `space` of `config` ("lin_rec709", "acescg", "lin_displayp3",
// "lin_adobergb"), matched by its name and its aliases in the config, case-insensitively; empty when MaterialX has
// none (Linear Rec.2020, ACES2065-1: the .mtlx then carries no colorspace and says so in its header).
std::string materialx_colorspace(const OcioConfigChoice& config, const std::string& space);

// glTF 2.0 defines its colours as linear Rec.709 and cannot name another space: a request with ExportFormat::gltf in
// another space (materialx_space, materialx_colorspace's name of it, other than "lin_rec709") is a UsageError saying
// so. `metalfit export` calls it before fitting; export_files calls it too.
void require_export_space(const ExportRequest& request, const std::string& space, const std::string& materialx_space);
// `--format all` means every format the space allows: outside linear Rec.709 glTF is taken out of `request` and the
// warning saying so is returned (empty when nothing was taken out). An explicit gltf stays, for require_export_space.
std::string leave_out_formats_the_space_cannot_carry(ExportRequest& request, const std::string& space,
                                                     const std::string& materialx_space);

// What a consumer must be told about an export before using it (one line each; `metalfit export` prints them on
// stderr): today, MaterialX documents in a space MaterialX cannot name.
std::vector<std::string> export_warnings(const FitRecordContext& context, const ExportRequest& request,
                                         const std::string& materialx_space);

// Writes all files below `dir` (created if missing) as one unit (update_folder_as_unit: staged in a folder beside
// `dir`, switched in with one rename; interrupted or failed, nothing changes). Files of an earlier export there stay;
// its index files (metalfit_export.json, cpp/metalfit_materials.hpp and the shared model files) are merged with the
// new entries, or the export is refused with an InputError saying why (another colour space or settings).
void write_export(const std::filesystem::path& dir, const std::vector<ExportFile>& files);

// The mechanical GLSL → HLSL translation of libfit's model functions (docs/export.md): a prelude of helpers plus a
// token mapping (vec3 → float3, bvec3 → bool3, vec3(…) → metalfit_vec3(…), mix/greaterThanEqual/equal → helpers).
std::string hlsl_from_glsl(std::string_view glsl);
// The prelude that makes the GLSL text of the model functions valid C++ (a float vec3 with GLSL's operators and the
// built-ins the models use), in namespace metalfit_shader.
std::string_view cpp_glsl_prelude();

}  // namespace metalfit
