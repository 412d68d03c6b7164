// The report folder written material by material (libfit/report/report_stream.hpp): each material's page staged and
// its report.json entry appended to a scratch file in the staging as its fit arrives; report.json and its script
// form are joined from the record's head, that file and its tail at the end.
#include "libfit/report/report_stream.hpp"

#include <fstream>
#include <map>
#include <stdexcept>
#include <unordered_map>

#include "libfit/base/errors.hpp"
#include "libfit/base/json_text.hpp"
#include "libfit/base/staged_folder.hpp"
#include "report/report_pages.hpp"
#include "report/report_parts.hpp"

namespace metalfit {
namespace {

using Json = nlohmann::ordered_json;

constexpr int kIndent = 1;  // as report_files dumps the record
constexpr std::string_view kMaterialsKey = "\n \"materials\": [";
constexpr std::string_view kScratch = "report.json.materials";  // in the staging only, removed before the switch

void write_or_fail(std::ofstream& out, std::string_view text, const std::filesystem::path& named) {
    out.write(text.data(), static_cast<std::streamsize>(text.size()));
    if (!out) throw InputError({named}, "cannot write");
}

}  // namespace

struct ReportStream::State {
    std::filesystem::path dir;
    ReportInputs inputs;
    const CostTable& table;
    std::optional<Budget> budget;
    Tolerance tolerance;
    ExportFormat target;
    StagedFolder folder;
    std::shared_ptr<const report_detail::ReportSwatches> swatches;
    CatalogSummaryBuilder summary;
    std::unordered_map<std::string, std::string> page_owner;  // page file → the id of its material
    std::filesystem::path scratch_path;
    std::ofstream scratch;
    std::size_t materials = 0;
    bool finished = false;

    State(const std::filesystem::path& d, const ReportInputs& in, const CostTable& t, std::optional<Budget> b,
          Tolerance tol, ExportFormat f)
        : dir(check_report_folder(d)),
          inputs(in),
          table(t),
          budget(std::move(b)),
          tolerance(tol),
          target(f),
          folder(dir, StagedFolder::Existing::replace_folder),
          swatches(report_detail::report_swatches(inputs)),
          scratch_path(folder.file(std::string(kScratch))),
          scratch(scratch_path, std::ios::binary) {
        if (!scratch) throw InputError({dir / kScratch}, "cannot write");
    }
};

ReportStream::ReportStream(const std::filesystem::path& dir, const ReportInputs& inputs, const CostTable& table,
                           std::optional<Budget> budget, Tolerance tolerance, ExportFormat target) {
    report_detail::require_chart_libraries();
    state_ = std::make_unique<State>(dir, inputs, table, std::move(budget), tolerance, target);
}

ReportStream::~ReportStream() = default;

void ReportStream::add(const MaterialFit& fit) {
    State& s = *state_;
    if (s.finished) throw std::logic_error("ReportStream: material added after finish");
    // report_files's checks, as each material comes: the first earlier material sharing its page (ids share pages).
    const std::string page = report_detail::material_page_file(fit.material);
    if (const auto owner = s.page_owner.find(page); owner != s.page_owner.end()) {
        if (owner->second == fit.material.id)
            throw UsageError("report: material " + fit.material.id + " is named twice (one page each)");
        throw UsageError("report: materials " + owner->second + " and " + fit.material.id + " would share one page (" +
                         page + ")");
    }
    s.page_owner.emplace(page, fit.material.id);
    s.summary.add(fit);
    const CostAndBudget cost = report_costs_of(fit, s.table, s.budget, s.tolerance, s.target);
    const ReportInputs inputs{s.inputs.fit,     s.inputs.colorimetry,    s.inputs.converter,
                              s.inputs.display, s.inputs.catalog,        cost,
                              s.inputs.renders, s.inputs.compare_sources};
    const Json entry = report_detail::material_record(fit, inputs, *s.swatches);
    write_or_fail(s.scratch,
                  (s.materials == 0 ? "\n" : ",\n") + std::string(2 * kIndent, ' ') +
                      indented_json(entry.dump(kIndent), 2, kIndent),
                  s.dir / "report.json");
    ++s.materials;
    s.folder.write(page, report_detail::material_page(fit.material));
    if (const auto render = report_detail::render_file(fit, inputs)) s.folder.write(render->path, render->contents);
}

void ReportStream::finish() {
    State& s = *state_;
    if (s.finished) throw std::logic_error("ReportStream: finished twice");
    s.finished = true;
    s.scratch.close();
    if (!s.scratch) throw InputError({s.dir / "report.json"}, "cannot write");
    const std::string whole =
        report_detail::report_record_without_materials(s.summary.summary(), s.inputs).dump(kIndent);
    const std::size_t at = whole.find(std::string(kMaterialsKey) + "]");
    if (at == std::string::npos) throw std::logic_error("ReportStream: the record has no materials member");
    const std::size_t cut = at + kMaterialsKey.size();
    const std::string head = whole.substr(0, cut);
    const std::string tail = (s.materials == 0 ? "" : "\n" + std::string(kIndent, ' ')) + whole.substr(cut) + "\n";
    // report.json, and the same bytes as a script: pages opened from file:// cannot fetch a JSON file.
    const auto join = [&](const std::filesystem::path& relative, std::string_view before, std::string_view after) {
        const std::filesystem::path named = s.dir / relative;
        std::ofstream out(s.folder.file(relative), std::ios::binary);
        write_or_fail(out, before, named);
        std::ifstream materials(s.scratch_path, std::ios::binary);
        if (s.materials > 0) out << materials.rdbuf();
        if (!materials) throw InputError({named}, "cannot write");
        write_or_fail(out, after, named);
        out.close();
        if (!out) throw InputError({named}, "cannot write");
    };
    join("report.json", head, tail);
    join("assets/report-data.js", "metalfitReport(" + head, tail + ");\n");
    std::filesystem::remove(s.scratch_path);
    for (const ReportFile& f : report_detail::fixed_report_files()) s.folder.write(f.path, f.contents);
    s.folder.commit();
}

}  // namespace metalfit
