// The export formats: one entry per format with its writer, the files it writes and what it can express. Everything
// that goes over the formats (export_files, the stand-in, the colour-space rules, the index merge, the help text)
// reads this list; a new format is one writer and one entry.
#pragma once

#include <array>
#include <optional>
#include <span>
#include <string>
#include <string_view>

#include "export/export_formats.hpp"

namespace metalfit::detail {

// Which models a format cannot write in their own form, and writes as the stand-in (expressible_stand_in) instead.
enum class StandInNeed {
    never,
    no_materialx_form,   // MaterialX: models whose MaterialxForm is stand_in (lazanyi-comp)
    not_f82_tint_curve,  // OpenPBR, Blender (4.0 - 4.2): every model that is not an F82-tint curve
};

struct ExportFormatEntry {
    ExportFormat format;
    // Every file of the format for the materials and models of an export.
    std::vector<ExportFile> (*write)(const std::vector<MaterialExport>& materials, const ExportContext& context);
    // The files it writes (docs/export.md), <stem> = <prefix>_<material>_<model>.
    std::string_view files;
    // The files it shares between exports into one folder merged with the one there (index_merge.cpp): the merged
    // text, or nothing when `relative` is not one of its shared files. Null for formats that share none. Throws
    // std::invalid_argument saying why the two cannot be merged.
    std::optional<std::string> (*merge_index)(const std::string& relative, const std::string& existing,
                                              const std::string& mine);
    StandInNeed stand_in;
    bool materialx_document;  // a MaterialX document: tagged with MaterialX's name of the colour space, if it has one
    bool linear_rec709_only;  // its colours can only be linear Rec.709 (glTF 2.0 cannot name another space)
    // A layered material is written as the format's own coat / thin film over the bare metal's constants (OpenPBR,
    // MaterialX, glTF), so the bare metal is fitted too (attach_bare_metal_fits); otherwise the stack's curve is.
    bool layers_over_bare_metal;
    // The curve its consumer evaluates for one exported model, with that curve's error figures (consumer_curve.hpp).
    ConsumerCurve (*consumer_curve)(const MaterialExport& material, const ModelExport& model, GamutPolicy gamut);
};

// Every format, in kExportFormatNames's order.
std::span<const ExportFormatEntry> export_format_entries();
const ExportFormatEntry& format_entry(ExportFormat format);

// Whether `format` writes `model` as the stand-in.
bool needs_stand_in(const ExportFormatEntry& format, const Model& model);

// The index merges of the formats (index_merge.cpp).
std::optional<std::string> merge_json_index(const std::string& relative, const std::string& existing,
                                            const std::string& mine);
std::optional<std::string> merge_glsl_index(const std::string& relative, const std::string& existing,
                                            const std::string& mine);
std::optional<std::string> merge_hlsl_index(const std::string& relative, const std::string& existing,
                                            const std::string& mine);
std::optional<std::string> merge_msl_index(const std::string& relative, const std::string& existing,
                                           const std::string& mine);
std::optional<std::string> merge_wgsl_index(const std::string& relative, const std::string& existing,
                                            const std::string& mine);
std::optional<std::string> merge_cpp_index(const std::string& relative, const std::string& existing,
                                           const std::string& mine);
// A file of an export written into `dir` where a file of that name is: the merged index file, or `mine` for a file
// no format shares. InputError naming the file when the two cannot be merged.
std::string merge_index(const std::filesystem::path& dir, const std::filesystem::path& relative,
                        const std::string& existing, const std::string& mine);

}  // namespace metalfit::detail
