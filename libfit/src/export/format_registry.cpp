#include "export/format_registry.hpp"

#include <algorithm>
#include <stdexcept>

namespace metalfit::detail {

namespace {

constexpr std::array kFormatEntries{
    ExportFormatEntry{ExportFormat::json, &export_json, "metalfit_export.json", &merge_json_index, StandInNeed::never,
                      false, false, false, &own_model_curve},
    ExportFormatEntry{ExportFormat::glsl, &export_glsl, "glsl/<stem>.glsl, glsl/metalfit_models.glsl",
                      &merge_glsl_index, StandInNeed::never, false, false, false, &own_model_curve},
    ExportFormatEntry{ExportFormat::hlsl, &export_hlsl, "hlsl/<stem>.hlsl, hlsl/metalfit_models.hlsl",
                      &merge_hlsl_index, StandInNeed::never, false, false, false, &own_model_curve},
    ExportFormatEntry{ExportFormat::mtlx, &export_mtlx, "mtlx/<stem>.mtlx", nullptr, StandInNeed::no_materialx_form,
                      true, false, true, &materialx_curve},
    ExportFormatEntry{ExportFormat::openpbr, &export_openpbr, "openpbr/<stem>.json, openpbr/<stem>.mtlx", nullptr,
                      StandInNeed::not_f82_tint_curve, true, false, true, &openpbr_curve},
    ExportFormatEntry{ExportFormat::cpp, &export_cpp,
                      "cpp/<stem>.hpp, cpp/metalfit_models.hpp, cpp/<prefix>_materials.hpp", &merge_cpp_index,
                      StandInNeed::never, false, false, false, &own_model_curve},
    ExportFormatEntry{ExportFormat::gltf, &export_gltf, "gltf/<stem>.gltf", nullptr, StandInNeed::never, false, true,
                      true, &gltf_curve},
    ExportFormatEntry{ExportFormat::blender, &export_blender, "blender/<stem>.py", nullptr,
                      StandInNeed::not_f82_tint_curve, false, false, false, &blender_curve},
    ExportFormatEntry{ExportFormat::msl, &export_msl, "msl/<stem>.metal, msl/metalfit_models.metal", &merge_msl_index,
                      StandInNeed::never, false, false, false, &own_model_curve},
    ExportFormatEntry{ExportFormat::wgsl, &export_wgsl, "wgsl/<stem>.wgsl, wgsl/metalfit_models.wgsl",
                      &merge_wgsl_index, StandInNeed::never, false, false, false, &own_model_curve},
};

// The entries and the names table list the formats in one order (the order of `--format all` and of the files).
constexpr bool same_order() {
    if (kFormatEntries.size() != kExportFormatNames.names.size()) return false;
    for (std::size_t i = 0; i < kFormatEntries.size(); ++i)
        if (kFormatEntries[i].format != kExportFormatNames.names[i].value) return false;
    return true;
}
static_assert(same_order(), "kFormatEntries and kExportFormatNames list the formats in one order");

}  // namespace

std::span<const ExportFormatEntry> export_format_entries() { return kFormatEntries; }

const ExportFormatEntry& format_entry(ExportFormat format) {
    for (const ExportFormatEntry& e : kFormatEntries)
        if (e.format == format) return e;
    throw std::logic_error("export: format without a registry entry");
}

bool needs_stand_in(const ExportFormatEntry& format, const Model& model) {
    switch (format.stand_in) {
        case StandInNeed::never: return false;
        case StandInNeed::no_materialx_form: return model.materialx_form() == MaterialxForm::stand_in;
        case StandInNeed::not_f82_tint_curve: return !model.is_f82_tint_curve();
    }
    return false;
}

}  // namespace metalfit::detail

namespace metalfit {

std::string to_string(ExportFormat format) { return std::string(kExportFormatNames.name(format)); }

}  // namespace metalfit
