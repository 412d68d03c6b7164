#include "glpreview/render/sheet_layout.hpp"

#include <algorithm>
#include <cmath>

#include "libfit/base/errors.hpp"
#include "libfit/base/number_text.hpp"
#include "libfit/models/model.hpp"

namespace metalfit::glpreview {

std::vector<std::string> sheet_model_groups(const SheetRequest& request) {
    return request.models.empty() ? std::vector<std::string>{kBestModel} : request.models;
}

std::string sheet_row_image(std::size_t row) { return "rows/" + std::to_string(row) + ".png"; }

void check_sheet_request(const SheetRequest& request) {
    for (std::size_t i = 0; i < request.models.size(); ++i) {
        if (request.models[i] != kBestModel) try {
                (void)find_model(request.models[i]);
            } catch (const UsageError& e) {
                throw UsageError(std::string("--sheet-models: ") + e.what());
            }
        if (std::find(request.models.begin(), request.models.begin() + i, request.models[i]) !=
            request.models.begin() + i)
            throw UsageError("--sheet-models: model '" + request.models[i] + "' named twice");
    }
    for (std::size_t i = 0; i < request.roughness.size(); ++i) {
        const double r = request.roughness[i];
        if (!(r >= 0.0 && r <= 1.0))
            throw UsageError("--sheet-roughness: each value must be in [0, 1] (GGX roughness)");
        if (std::find(request.roughness.begin(), request.roughness.begin() + i, r) != request.roughness.begin() + i)
            throw UsageError("--sheet-roughness: a roughness named twice");
    }
}

std::vector<SheetColumn> sheet_columns(int model_groups, int roughness_values) {
    std::vector<SheetColumn> columns;
    for (int r = 0; r < roughness_values; ++r) columns.push_back({SheetCellKind::reference, 0, r});
    for (int g = 1; g <= model_groups; ++g)
        for (int r = 0; r < roughness_values; ++r) {
            columns.push_back({SheetCellKind::model, g, r});
            columns.push_back({SheetCellKind::difference, g, r});
        }
    return columns;
}

int sheet_column(SheetCellKind kind, int group, int roughness, int roughness_values) {
    if (kind == SheetCellKind::reference) return roughness;
    return roughness_values + (group - 1) * 2 * roughness_values + 2 * roughness +
           (kind == SheetCellKind::difference ? 1 : 0);
}

int label_band_height(int cell_height) { return std::clamp(static_cast<int>(std::lround(cell_height * 0.08)), 8, 28); }

std::vector<TextBox> sheet_labels(const std::vector<SheetCell>& cells, int cell_width, int cell_height,
                                  const ErrorScale& scale) {
    const int band = std::min(label_band_height(cell_height), cell_height / 2);
    const int font = std::max(6, band - 2);
    std::vector<TextBox> boxes;
    for (const SheetCell& c : cells) {
        const int x = c.column * cell_width, y = c.row * cell_height;
        std::string top, bottom = "roughness " + significant_text(c.roughness, 6) + (c.lit ? ", lit" : "");
        switch (c.kind) {
            case SheetCellKind::reference: top = c.material + ": reference"; break;
            case SheetCellKind::model:
                top = c.material + ": " + c.model + (c.best ? " (best)" : "");
                bottom += ", rel_rms " + significant_text(100.0 * c.error, 2) + "%";
                break;
            case SheetCellKind::difference:
                top = c.model + " / ref - 1";
                bottom += ", " + scale_label(scale);
                break;
        }
        boxes.push_back({x, y, cell_width, band, top, font});
        boxes.push_back({x, y + cell_height - band, cell_width, band, bottom, font});
    }
    return boxes;
}

CellRect colour_bar_rect(int column, int row, int cell_width, int cell_height) {
    const int band = std::min(label_band_height(cell_height), cell_height / 2);
    const int width = std::max(3, cell_width / 24), margin = std::max(1, cell_width / 64);
    return {column * cell_width + cell_width - width - margin, row * cell_height + band + margin, width,
            std::max(1, cell_height - 2 * band - 2 * margin)};
}

}  // namespace metalfit::glpreview
