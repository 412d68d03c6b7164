// metalfit report: the fits of one or many materials as a folder a person opens in a browser (docs/report.md):
// index.html (the catalog), materials/<id>.html, report.json (schema metalfit.report/1, the one source of every
// number the pages show) and assets/ (the chart libraries, the page script, the renders). Deterministic: the same
// inputs give byte-identical files (no dates, no absolute paths).
#pragma once

#include <nlohmann/json.hpp>

#include <filesystem>
#include <string>
#include <vector>

#include "libfit/base/atomic_file.hpp"
#include "libfit/color/color_space.hpp"
#include "libfit/color/colorimetry.hpp"
#include "libfit/color/display_transform.hpp"
#include "libfit/fit/fit.hpp"
#include "libfit/fit/fit_record.hpp"
#include "libfit/io/catalog.hpp"
#include "libfit/report/model_costs.hpp"
#include "libfit/report/sphere_renders.hpp"

namespace metalfit {

inline constexpr const char* kReportSchema = "metalfit.report/1";

// Everything the report is made from besides the fits.
struct ReportInputs {
    const FitRecordContext& fit;           // the colour pipeline and error settings of the fits
    const Colorimetry& colorimetry;        // ... as objects, for the curves the pages plot
    const ColorSpaceConverter& converter;  // the working space of the fits
    const DisplayTransform& display;       // scene_linear → display, for colour stripes and swatches
    const Catalog& catalog;                // kinds, DOIs, licences and the alternate sources of catalog materials
    const CostAndBudget& cost;
    const SphereRenders& renders;
    // Compare a catalog material's sources (`--sources all`): F0 and F82 of every measurement the catalog holds and
    // their spread; false (`--sources primary`): only the source fitted, `data_sources` is null.
    bool compare_sources = true;
};

// The record (docs/report.md). `fits` as fit_materials gives them (the same models in the same order).
nlohmann::ordered_json report_record(const std::vector<MaterialFit>& fits, const ReportInputs& inputs);

// A file of the report folder: `path` relative to it. The files every writer writes (libfit/base/atomic_file.hpp), so
// that they go to the folder's writer as they are.
using ReportFile = OutputFile;

// Every file of the report folder: the pages, report.json, its script form assets/report-data.js (the same
// bytes, wrapped so that pages opened from file:// can load it), the chart libraries, the page script and style,
// and the renders. Throws std::logic_error when this libfit was built without the chart libraries.
std::vector<ReportFile> report_files(const std::vector<MaterialFit>& fits, const ReportInputs& inputs);

// Writes the folder as one unit (replace_folder_as_unit, libfit/base/staged_folder.hpp): every file into a staging
// folder beside `dir`, which is then exchanged with `dir` (at every instant the old or the new folder is there; the
// old one is removed after). On failure or a signal nothing new is left behind; a staging folder a SIGKILL left is
// removed by the next writer. Throws InputError naming the path that failed.
void write_report_folder(const std::filesystem::path& dir, const std::vector<ReportFile>& files);

// What write_report_folder checks before writing (the target is a folder or does not exist, in an existing folder),
// for a caller to fail before the work; returns the folder without a trailing separator. Throws InputError.
std::filesystem::path check_report_folder(const std::filesystem::path& dir);

}  // namespace metalfit
