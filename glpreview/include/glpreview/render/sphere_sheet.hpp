// The sphere sheet (the QA sheet): for each metal a row reference | model | |difference| × 10, per model asked for
// (or the best fitted one) and per roughness asked for (or the scene sphere's), each cell the GPU render of one
// sphere in the same scene (a distance-impostor room by default), labelled on sheet.png (sheet_layout.hpp).
#pragma once

#include <filesystem>
#include <functional>
#include <string>
#include <vector>

#include <nlohmann/json.hpp>

#include "glpreview/gl/gl_context.hpp"
#include "glpreview/render/preview.hpp"
#include "glpreview/render/sheet_layout.hpp"
#include "glpreview/scene/scene.hpp"

namespace metalfit::glpreview {

inline constexpr double kSheetDifferenceScale = 10.0;

struct SphereSheet {
    // per row, model group and roughness: material, model, its worst-channel rel_rms, image RMSE, roughness and the
    // columns of its reference, model and difference cells (sheet.json)
    nlohmann::ordered_json record;
    std::vector<std::filesystem::path> written;  // sheet.exr, sheet.png, sheet.json in options.output_dir
};

// The sheet as a pass graph: sheet-fresnel (reference LUT and the models per material) → the environment
// (capture-environment for rooms, load-equirect for an image at infinity; prefilter-environment or
// downsample-environment when a roughness column calls for it) → sheet-cells (every cell on the GPU) →
// sheet-labels (when asked) → the three files. `scene` must hold exactly one sphere (its position, reflection mode,
// iterations and glossy method are used for every cell). `context` may be null: one is made for the GPU passes.
// The sheet's graph compiled without running it (no GL, no fits): what --explain --sheet prints.
Plan build_sheet_plan(const Scene& scene, const SheetRequest& request);

// `before_commit` as run_preview's: the sheet before its files are switched in.
SphereSheet render_sphere_sheet(const Scene& scene, const SheetRequest& request, const PreviewOptions& options,
                                GlContext* context = nullptr,
                                const std::function<void(const SphereSheet&)>& before_commit = {});

}  // namespace metalfit::glpreview
