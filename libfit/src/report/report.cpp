// The files of the report folder (layout in docs/report.md).
#include "libfit/report/report.hpp"

#include "libfit/base/errors.hpp"
#include "report/report_pages.hpp"
#include "report/report_parts.hpp"
#include "report_assets.hpp"

namespace metalfit {
namespace {

// three.js's ES modules as JSON strings in a classic script, which viewer.js imports through blob: URLs: Chromium
// refuses a module script loaded from file:// (its origin is opaque), not one from a blob: URL of the page.
std::string three_script() {
    nlohmann::ordered_json modules = nlohmann::ordered_json::object();
    for (const auto& [name, text] : report_detail::kThreeModules) modules[std::string(name)] = std::string(text);
    return "// three.js (MIT licence: LICENSE.three.txt), its ES modules as text for viewer.js (docs/report.md)\n"
           "metalfitThree(" +
           modules.dump() + ");\n";
}

}  // namespace

void report_detail::require_chart_libraries() {
    if (!report_detail::kHasChartLibraries)
        throw UsageError("report: this metalfit was built without the chart libraries (node_modules/ was missing when "
                         "it was configured): run scripts/install-deps.sh, then reconfigure and rebuild");
}

std::vector<ReportFile> report_detail::fixed_report_files() {
    std::vector<ReportFile> files;
    files.push_back({"index.html", report_detail::catalog_page()});
    for (const auto& [name, text] : report_detail::kReportAssets)
        files.push_back({"assets/" + std::string(name), std::string(text)});
    files.push_back({"assets/three.js", three_script()});
    return files;
}

std::optional<ReportFile> report_detail::render_file(const MaterialFit& fit, const ReportInputs& inputs) {
    if (!inputs.renders.rows) return std::nullopt;
    const std::optional<std::size_t> row = inputs.renders.rows->row_of(fit.material.id);
    if (!row) return std::nullopt;
    return ReportFile{report_detail::render_image_file(fit.material.id), inputs.renders.rows->image_bytes(*row)};
}

std::vector<ReportFile> report_files(const std::vector<MaterialFit>& fits, const ReportInputs& inputs) {
    report_detail::require_chart_libraries();
    for (std::size_t i = 0; i < fits.size(); ++i)
        for (std::size_t j = 0; j < i; ++j)
            if (fits[i].material.id == fits[j].material.id)
                throw UsageError("report: material " + fits[i].material.id + " is named twice (one page each)");
            else if (report_detail::material_page_file(fits[i].material) ==
                     report_detail::material_page_file(fits[j].material))
                throw UsageError("report: materials " + fits[j].material.id + " and " + fits[i].material.id +
                                 " would share one page (" + report_detail::material_page_file(fits[i].material) + ")");
    const std::string record = report_record(fits, inputs).dump(1) + "\n";
    std::vector<ReportFile> files = report_detail::fixed_report_files();
    for (const MaterialFit& fit : fits) {
        files.push_back({report_detail::material_page_file(fit.material), report_detail::material_page(fit.material)});
        if (auto render = report_detail::render_file(fit, inputs)) files.push_back(std::move(*render));
    }
    files.push_back({"report.json", record});
    // The same bytes as report.json, as a script: pages opened from file:// cannot fetch a JSON file.
    files.push_back({"assets/report-data.js", "metalfitReport(" + record + ");\n"});
    return files;
}

}  // namespace metalfit
