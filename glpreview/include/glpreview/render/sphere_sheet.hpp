// The sphere sheet of the main job: for each metal a row reference | best fitted model | |difference| × 10, each
// cell the GPU render of one sphere in the same scene (a distance-impostor room by default).
#pragma once

#include <filesystem>
#include <string>
#include <vector>

#include <nlohmann/json.hpp>

#include "glpreview/gl/gl_context.hpp"
#include "glpreview/render/preview.hpp"
#include "glpreview/scene/scene.hpp"

namespace metalfit::glpreview {

inline constexpr double kSheetDifferenceScale = 10.0;

struct SphereSheet {
    nlohmann::ordered_json record;            // per row: material, model, its worst-channel rel_rms, image RMSE
    std::vector<std::filesystem::path> written;  // sheet.exr, sheet.png, sheet.json in options.output_dir
};

// The sheet as a pass graph: sheet-fresnel (reference LUT and best fitted model per material) → the environment
// (capture-environment for rooms, load-equirect for an image at infinity)
// → sheet-cells (every cell on the GPU) → the three files. `scene` must hold exactly one sphere (its position,
// reflection mode and iterations are used for every cell). `context` may be null: one is made for the GPU passes.
// The sheet's graph compiled without running it (no GL, no fits): what --explain --sheet prints.
Plan build_sheet_plan(const Scene& scene, const std::vector<std::string>& materials);

SphereSheet render_sphere_sheet(const Scene& scene, const std::vector<std::string>& materials, const PreviewOptions& options,
                                GlContext* context = nullptr);

}  // namespace metalfit::glpreview
