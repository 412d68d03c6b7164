// What a sphere sheet shows and where (no GL): the columns for a list of models and roughness values, and the label
// of every cell (material, model, roughness, error) with the bands it is drawn in (docs/preview.md, "The sheet").
#pragma once

#include <string>
#include <vector>

#include "glpreview/io/image_text.hpp"

namespace metalfit::glpreview {

// What the sheet is asked for. Empty `models`: each material's best fitted model (one group); empty `roughness`:
// the scene sphere's own roughness (one column per group): the sheet of before.
struct SheetRequest {
    std::vector<std::string> materials;  // one row each
    std::vector<std::string> models;     // libfit model ids, in the order shown
    std::vector<double> roughness;       // GGX roughness of the columns, each in [0, 1]
    bool labels = true;                  // drawn on sheet.png (sheet.exr stays the bare renders)
    bool light = false;  // one more column: roughness kSheetLightRoughness under a point light grazing the sphere
};

// The lit column's roughness: a point light's highlight needs a lobe.
inline constexpr double kSheetLightRoughness = 0.35;

// Throws UsageError (one line, naming the option) for an unknown model, a model or roughness named twice, or a
// roughness outside [0, 1].
void check_sheet_request(const SheetRequest& request);

enum class SheetCellKind { reference, model, difference };

// Column groups: the reference at every roughness, then per model group its model and |difference| × 10 at every
// roughness, side by side: reference(r…) | model₁ r₁, |Δ₁| r₁, model₁ r₂, |Δ₁| r₂, … | model₂ …
struct SheetColumn {
    SheetCellKind kind;
    int group;      // 0: the reference; g ≥ 1: the g-th model group
    int roughness;  // index into the roughness list
};
std::vector<SheetColumn> sheet_columns(int model_groups, int roughness_values);
// The column of a cell (the inverse of sheet_columns).
int sheet_column(SheetCellKind kind, int group, int roughness, int roughness_values);

// One cell's facts, what its label says.
struct SheetCell {
    int row = 0, column = 0;
    SheetCellKind kind = SheetCellKind::reference;
    std::string material, model;  // model: empty for the reference
    double roughness = 0;
    double error = 0;  // model: worst-channel fitted rel_rms; difference: image RMSE; reference: unused
    bool lit = false;  // the light column (a point light grazing the sphere)
};

// The two label bands of a cell: its top and bottom rows of label_band_height(cell_height) pixels. Nothing else of the
// sheet is drawn on.
int label_band_height(int cell_height);
// Per cell, in ASCII (OpenImageIO 2.4's render_text draws one glyph per byte): top band "material: model"
// (reference: "material: reference"; difference: "|model - ref| x 10"), bottom band "roughness r" and the error
// (model: ", rel_rms 0.12%", the fit's worst channel; difference: ", RMSE 0.0003", of the two cells' pixels).
std::vector<TextBox> sheet_labels(const std::vector<SheetCell>& cells, int cell_width, int cell_height);

}  // namespace metalfit::glpreview
