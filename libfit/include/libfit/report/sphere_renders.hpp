// The sphere renders of a report: glpreview's sphere sheet, one image per material (glpreview --sheet --sheet-rows: a
// row reference | model | its signed error view per model of the report), made by running the glpreview executable
// once for every material, so that libfit and the metalfit CLI never link OpenGL (docs/decisions.md).
#pragma once

#include <filesystem>
#include <functional>
#include <memory>
#include <optional>
#include <string>
#include <vector>

#include "libfit/base/enum_names.hpp"
#include "libfit/color/color_space.hpp"

namespace metalfit {

enum class RenderMode { auto_, on, off };
inline constexpr EnumNames kRenderModeNames{"--renders mode", KnownNamesWording::alternatives,
                                            std::array{EnumName<RenderMode>{RenderMode::auto_, "auto"},
                                                       EnumName<RenderMode>{RenderMode::on, "on"},
                                                       EnumName<RenderMode>{RenderMode::off, "off"}}};
RenderMode parse_render_mode(const std::string& text);  // "auto" | "on" | "off", else UsageError

// Where one model's render of one material at one roughness lies in the sheet (columns; the row is the material's).
struct SphereSheetCells {
    double roughness = 0;
    int reference = 0, model = 0, difference = 0;
    double image_rmse = 0;  // of the model cell against the reference cell (linear radiance)
    // The difference cell's error-view scale (|model / reference − 1| from `smallest` to `largest`, log), the row's.
    double error_smallest = 0, error_largest = 0;
};

// Where glpreview left the row images until the report is written (removed when the last copy of the renders goes).
class RenderScratchFolder;

// The renders: row r shows materials[r], in its own image.
struct SphereRowImages {
    std::shared_ptr<const RenderScratchFolder> scratch;
    std::vector<std::filesystem::path> images;                      // images[r]: row r's labelled PNG, in `scratch`
    std::vector<std::string> materials;                             // row r shows materials[r] ...
    std::vector<std::string> models;                                // ... with a column group per model, in this order
    std::vector<std::vector<std::vector<SphereSheetCells>>> cells;  // cells[r][m]: row r, models[m], per roughness
    int cell_width = 0, cell_height = 0;

    // The row of a material (by its id), if it has one.
    std::optional<std::size_t> row_of(const std::string& material) const;
    // The bytes of row r's PNG (InputError naming the file when it cannot be read).
    std::string image_bytes(std::size_t row) const;
};

// The row images, or why there are none ("renders skipped: <reason>" on the pages).
struct SphereRenders {
    std::optional<SphereRowImages> rows;
    std::string skipped;
};

struct SphereRenderRequest {
    std::filesystem::path glpreview;     // the executable (glpreview_beside_this_program() by default)
    std::filesystem::path scene;         // a scene with one sphere (data/scenes/sheet.json)
    std::vector<std::string> materials;  // catalog ids, named finishes or files (as the user gave them)
    std::vector<std::string> ids;        // the id of each row's material in the records (empty: `materials`)
    std::string film, coat;              // layers over every material, as --film/--coat ("" = none)
    std::vector<std::string> models;     // libfit model ids (the report's), one column group each
    std::filesystem::path data_dir;
    OcioConfigChoice ocio;
    int cell_size = 160;  // pixels, square cells
    // Called as glpreview finishes each row (rows done, rows in all; glpreview --sheet-progress); none: no progress.
    std::function<void(std::size_t, std::size_t)> progress = {};
};

// glpreview in the directory of the running executable (empty when it is not there).
std::filesystem::path glpreview_beside_this_program();

// Runs glpreview --sheet MATERIALS --sheet-models MODELS --sheet-rows (the scene sphere's roughness: the mirror of
// sheet.json) in a temporary folder, removed when the renders go (the row images stay on disk, not in memory, until
// the report copies each into its folder). `off`: skipped ("--renders off"); `auto`:
// any failure (no glpreview, no EGL context, ...) becomes the skipped reason; `on`: a failure throws InputError
// naming glpreview and its last line of error output.
SphereRenders render_spheres(const SphereRenderRequest& request, RenderMode mode);

}  // namespace metalfit
