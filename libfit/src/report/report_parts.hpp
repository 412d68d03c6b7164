// The report in parts, which report_files joins and ReportStream writes material by material (the same bytes):
// report.json without its materials and one material's entry (report_record.cpp), the files every report holds
// (report.cpp).
#pragma once

#include <memory>
#include <optional>

#include <nlohmann/json.hpp>

#include "libfit/fit/catalog_summary.hpp"
#include "libfit/report/report.hpp"

namespace metalfit::report_detail {

// The display colours of the stripes and swatches (an OCIO processor to scene_linear and the display transform).
class ReportSwatches;
std::shared_ptr<const ReportSwatches> report_swatches(const ReportInputs& inputs);

// One element of the record's "materials": its render row looked up in inputs.renders, its cost marks in inputs.cost.
nlohmann::ordered_json material_record(const MaterialFit& fit, const ReportInputs& inputs,
                                       const ReportSwatches& swatches);

// The record with "materials" an empty array, in its place.
nlohmann::ordered_json report_record_without_materials(const CatalogSummary& summary, const ReportInputs& inputs);

// UsageError when this libfit was built without the chart libraries.
void require_chart_libraries();
// index.html, the chart libraries, the page script and style and three.js: every file but the material pages, their
// renders, report.json and assets/report-data.js.
std::vector<ReportFile> fixed_report_files();
// A material's renders (its row of glpreview's sheet, render_image_file), when glpreview rendered it.
std::optional<ReportFile> render_file(const MaterialFit& fit, const ReportInputs& inputs);

}  // namespace metalfit::report_detail
