// What a sphere sheet shows and where (no GL): the columns for a list of models and roughness values, and the label
// of every cell (material, model, roughness, error) with the bands it is drawn in (docs/preview.md, "The sheet").
#pragma once

#include <functional>
#include <string>
#include <vector>

#include "glpreview/io/image_text.hpp"
#include "glpreview/render/error_view.hpp"

namespace metalfit::glpreview {

// What the sheet is asked for. `models` may name kBestModel beside libfit ids (each material's best fitted model, a
// group of its own); empty `models` is {kBestModel}; empty `roughness`: the scene sphere's own roughness (one column
// per group): the sheet of before.
struct SheetRequest {
    std::vector<std::string> materials;  // one row each
    std::vector<std::string> models;     // libfit model ids or kBestModel, in the order shown
    std::vector<double> roughness;       // GGX roughness of the columns, each in [0, 1]
    bool labels = true;                  // drawn on sheet.png (sheet.exr stays the bare renders)
    bool light = false;  // one more column: roughness kSheetLightRoughness under a point light grazing the sphere
    std::string film = {}, coat = {};  // layers over every row's metal, as metalfit's --film/--coat ("" = none)
    // Called after each row is rendered (rows done, rows in all): `--sheet-progress`, metalfit report's progress.
    std::function<void(std::size_t, std::size_t)> on_row = {};
    // `--sheet-rows`: each row its own labelled image, rows/<row>.png (row counted from 0), written as the row is done
    // (its error views on the row's own scale), and its entries appended to sheet.json; no sheet.exr or sheet.png,
    // and the returned record (SphereSheet::record) is empty. The sheet's memory is then one row's, whatever the
    // number of materials: each row's Fresnel is made when the row is rendered and let go after it (metalfit report's
    // renders).
    bool row_images = false;
};

// The image of row `row` in a --sheet-rows sheet's folder: "rows/<row>.png".
std::string sheet_row_image(std::size_t row);

inline constexpr const char* kBestModel = "best";
// The model groups a request shows: its models, or {kBestModel} when it names none.
std::vector<std::string> sheet_model_groups(const SheetRequest& request);

// The lit column's roughness: a point light's highlight needs a lobe.
inline constexpr double kSheetLightRoughness = 0.35;

// Throws UsageError (one line, naming the option) for an unknown model, a model (or best) or roughness named twice, or
// a roughness outside [0, 1].
void check_sheet_request(const SheetRequest& request);

enum class SheetCellKind { reference, model, difference };

// Column groups: the reference at every roughness, then per model group its model and its difference at every
// roughness, side by side: reference(r…) | model₁ r₁, Δ₁ r₁, model₁ r₂, Δ₁ r₂, … | model₂ …
// In sheet.exr a difference cell holds |model − reference| × kSheetDifferenceScale (linear, numbers to read back);
// in sheet.png it shows the signed false-colour error view (render/error_view.hpp) with its colour bar.
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
    double error = 0;   // model: worst-channel fitted rel_rms; difference: image RMSE; reference: unused
    bool lit = false;   // the light column (a point light grazing the sphere)
    bool best = false;  // the model is the material's best fitted one (asked for as kBestModel)
    // A difference cell's two sources (−1 for the other kinds).
    int model_column = -1, reference_column = -1;
};

// The two label bands of a cell: its top and bottom rows of label_band_height(cell_height) pixels. Nothing else of the
// sheet is drawn on.
int label_band_height(int cell_height);
// Per cell, in ASCII (OpenImageIO 2.4's render_text draws one glyph per byte): top band "material: model"
// ("material: model (best)" for a best fit; reference: "material: reference"; difference: "model / ref - 1"),
// bottom band "roughness r" and the error (model: ", rel_rms 0.12%", the fit's worst channel; difference: the error
// view's scale, ", +-1e-05..0.01 log").
std::vector<TextBox> sheet_labels(const std::vector<SheetCell>& cells, int cell_width, int cell_height,
                                  const ErrorScale& scale);

// Where a difference cell's colour bar goes: a strip at the cell's right edge, between its label bands.
struct CellRect {
    int x = 0, y = 0, width = 0, height = 0;
};
CellRect colour_bar_rect(int column, int row, int cell_width, int cell_height);

}  // namespace metalfit::glpreview
