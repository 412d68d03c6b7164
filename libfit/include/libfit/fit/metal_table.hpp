// The all-metals colour table (`metalfit table`): per catalog material its F0 = R_c(1) and its F82 tint
// (R_c(1/7) / Schlick(F0, 1/7), the f82-tint model's closed form, as OpenPBR's specular_color and Adobe's metal
// table use), linear in the working space and as 8-bit display values and hex through the OCIO display transform,
// with the material's source, reference and caveat. Like physicallybased.info's table, for colour pickers.
#pragma once

#include <array>
#include <functional>
#include <string>
#include <vector>

#include <nlohmann/json.hpp>

#include "libfit/color/color.hpp"
#include "libfit/color/color_space.hpp"
#include "libfit/color/colorimetry.hpp"
#include "libfit/color/display_transform.hpp"
#include "libfit/io/catalog.hpp"
#include "libfit/reference/reference_curve.hpp"

namespace metalfit {

using Display8 = std::array<unsigned char, 3>;

struct MetalTableRow {
    std::string id, name, kind, source, reference, note;
    RGB f0, tint;  // linear, in the table's working space (may leave [0, 1]: flagged in the outputs)
    Display8 f0_display{}, tint_display{};  // 8-bit display-referred (clamped to [0, 1] by the transform)
    std::string stack;                      // the layers over the metal (describe_stack); empty for a bare one
    nlohmann::ordered_json stack_record;    // their provenance (stack_record); null for a bare one
};

struct MetalTable {
    std::string space;    // the working space of the linear values
    std::string display;  // the display transform of the 8-bit values ("Linear Rec.709 (sRGB) → sRGB - Display / …")
    std::vector<MetalTableRow> rows;
};

// The colour pipeline of the table: the linear values in `working`, the 8-bit ones from `scene_linear` values (the
// display transform's input) through `display`.
struct MetalTableColour {
    const Colorimetry& colorimetry;
    const ColorSpaceConverter& working;
    const ColorSpaceConverter& scene_linear;
    const DisplayTransform& display;
    SpectralOptions spectral;
};

// Every catalog material's primary source, in catalog order.
MetalTable metal_table(const Catalog& catalog, const MetalTableColour& colour);
// The materials `loaders` load, in order (catalog or file materials, with layers when they have them: `metalfit
// table Ti --film TiO2:80nm`); `catalog` gives a catalog material's kind and reference.
MetalTable metal_table(const std::vector<std::function<Material()>>& loaders, const Catalog& catalog,
                       const MetalTableColour& colour);

// Linear colours of the display transform's input as 8-bit display values (one OCIO apply for all of them).
std::vector<Display8> display_colours(const std::vector<RGB>& linear, const DisplayTransform& display);

// "#rrggbb" (lower case).
std::string hex(const Display8& rgb);

// The three renderings of `metalfit table --format`: one row per material.
std::string metal_table_csv(const MetalTable& table);
std::string metal_table_markdown(const MetalTable& table);
nlohmann::ordered_json metal_table_json(const MetalTable& table);

}  // namespace metalfit
