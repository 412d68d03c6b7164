// The sphere renders of a report: glpreview's sphere sheet (one row per material: reference | best fitted model |
// |difference| × 10), made by running the glpreview executable, so that libfit and the metalfit CLI never link
// OpenGL (docs/decisions.md).
#pragma once

#include <filesystem>
#include <optional>
#include <string>
#include <vector>

#include "libfit/color/color_space.hpp"

namespace metalfit {

enum class RenderMode { auto_, on, off };
RenderMode parse_render_mode(const std::string& text);  // "auto" | "on" | "off", else UsageError

struct SphereSheetImage {
    std::string png;                     // the bytes of glpreview's sheet.png
    std::vector<std::string> materials;  // row r shows materials[r] ...
    std::vector<std::string> models;     // ... next to models[r], the model glpreview chose for it
    int cell_width = 0, cell_height = 0;
};

// The sheet, or why there is none ("renders skipped: <reason>" on the pages).
struct SphereRenders {
    std::optional<SphereSheetImage> sheet;
    std::string skipped;
};

struct SphereRenderRequest {
    std::filesystem::path glpreview;     // the executable (glpreview_beside_this_program() by default)
    std::filesystem::path scene;         // a scene with one sphere (data/scenes/sheet.json)
    std::vector<std::string> materials;  // catalog ids
    std::filesystem::path data_dir;
    OcioConfigChoice ocio;
    int cell_size = 160;                 // pixels, square cells
};

// glpreview in the directory of the running executable (empty when it is not there).
std::filesystem::path glpreview_beside_this_program();

// Runs glpreview --sheet in a temporary folder (removed afterwards). `off`: skipped ("--renders off"); `auto`:
// any failure (no glpreview, no EGL context, ...) becomes the skipped reason; `on`: a failure throws InputError
// naming glpreview and its last line of error output.
SphereRenders render_spheres(const SphereRenderRequest& request, RenderMode mode);

}  // namespace metalfit
