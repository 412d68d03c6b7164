// The fit record written material by material: the same text as fit_record(...).dump(2), byte for byte, without
// holding more than one material's record (what `metalfit fit --all --json` writes for thousands of materials).
#pragma once

#include <functional>
#include <string>
#include <string_view>
#include <unordered_set>

#include "libfit/fit/budget.hpp"
#include "libfit/fit/fit.hpp"
#include "libfit/fit/fit_record.hpp"

namespace metalfit {

class FitRecordStream {
public:
    using Write = std::function<void(std::string_view text)>;

    // `write` receives the text in order; the record is whole once finish() returned.
    FitRecordStream(FitRecordContext context, Write write);

    // The next material, in the order of the record; `budget` for every material or for none, as fit_record takes
    // them. A material whose id was already written is left out: fit_record, whose "materials" is a JSON object,
    // keeps one entry per id (the same material named twice gives the same entry).
    // `recommendation`: the material's "recommendation" (material_record), when given.
    void add(const MaterialFit& fit, const BudgetChoice* budget = nullptr,
             const nlohmann::ordered_json* recommendation = nullptr);

    // The end of the record (without the final newline of `metalfit fit --json`).
    void finish();

private:
    void write_head(const BudgetChoice* first_budget);

    FitRecordContext context_;
    Write write_;
    bool head_written_ = false;
    bool finished_ = false;
    std::unordered_set<std::string> ids_;
};

}  // namespace metalfit
