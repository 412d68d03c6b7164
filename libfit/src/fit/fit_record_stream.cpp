#include "libfit/fit/fit_record_stream.hpp"
#include "libfit/base/json_text.hpp"

#include <stdexcept>
#include <utility>

namespace metalfit {
namespace {

constexpr int kIndent = 2;  // as `metalfit fit --json` dumps the record

}  // namespace

FitRecordStream::FitRecordStream(FitRecordContext context, Write write)
    : context_(std::move(context)), write_(std::move(write)) {}

void FitRecordStream::write_head(const BudgetChoice* first_budget) {
    // The record without materials ends with `"materials": {}` and the closing brace: the head is everything up to
    // and including the materials' opening brace.
    const std::string whole = fit_record_without_materials(context_, first_budget).dump(kIndent);
    const std::string empty_end = "{}\n}";
    if (whole.size() < empty_end.size() ||
        whole.compare(whole.size() - empty_end.size(), empty_end.size(), empty_end) != 0)
        throw std::logic_error("FitRecordStream: the record does not end with its materials");
    write_(std::string_view(whole).substr(0, whole.size() - empty_end.size() + 1));
    head_written_ = true;
}

void FitRecordStream::add(const MaterialFit& fit, const BudgetChoice* budget,
                          const nlohmann::ordered_json* recommendation) {
    if (finished_) throw std::logic_error("FitRecordStream: material added after finish");
    if (!head_written_) write_head(budget);
    if (!ids_.insert(fit.material.id).second) return;
    const nlohmann::ordered_json key = fit.material.id;
    const std::string margin(2 * kIndent, ' ');
    write_((ids_.size() == 1 ? "\n" : ",\n") + margin + key.dump() + ": " +
           indented_json(material_record(fit, context_.data_dir, budget, recommendation).dump(kIndent), 2, kIndent));
}

void FitRecordStream::finish() {
    if (finished_) throw std::logic_error("FitRecordStream: finished twice");
    if (!head_written_) {
        write_head(nullptr);
        write_("}\n}");
    } else {
        write_(ids_.empty() ? "}\n}" : "\n" + std::string(kIndent, ' ') + "}\n}");
    }
    finished_ = true;
}

}  // namespace metalfit
