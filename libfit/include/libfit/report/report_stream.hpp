// The report folder written material by material (`metalfit report --all`): each material's page and report.json
// entry are made as its fit arrives and the fit is let go; the catalog summary, the cost marks and the --fail-above
// lines keep a few numbers per material. The folder is byte for byte report_files + write_report_folder's for the
// same fits, and is switched in as one unit the same way (docs/decisions.md, "Streamed export and report").
#pragma once

#include <filesystem>
#include <memory>
#include <optional>

#include "libfit/report/report.hpp"

namespace metalfit {

class ReportStream {
public:
    // `inputs.cost` holds the cost table's costs and the budget (report_costs with no fits); each material's choice
    // and recommendation are made here (report_costs_of). The objects `inputs` refers to must outlive the stream.
    // The staging folder is made here (InputError as write_report_folder); nothing is in `dir` before finish().
    ReportStream(const std::filesystem::path& dir, const ReportInputs& inputs, const CostTable& table,
                 std::optional<Budget> budget, Tolerance tolerance, ExportFormat target);
    ~ReportStream();
    ReportStream(const ReportStream&) = delete;
    ReportStream& operator=(const ReportStream&) = delete;

    // The next material (UsageError as report_files when its id or page is another's).
    void add(const MaterialFit& fit);
    // Writes report.json, its script form, the catalog page and the assets, and switches the folder in.
    void finish();

private:
    struct State;
    std::unique_ptr<State> state_;
};

}  // namespace metalfit
