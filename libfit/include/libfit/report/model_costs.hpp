// What the report shows about cost and budget, and nothing more: the cost of each model (when a cost table is
// given) and, per material, the model chosen for a budget (when one is asked). The report does not compute
// either: the cost table and the "cheapest model meeting a budget" choice belong to the fit stage's model
// selection; the report only shows what it is handed here.
#pragma once

#include <map>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

#include "libfit/export/recommendation.hpp"
#include "libfit/fit/budget.hpp"
#include "libfit/fit/model_cost.hpp"

namespace metalfit {

// One cost per model id, in one unit, and where the numbers come from ("metalfit bench --json FILE", "SPIR-V
// operation counts"): what the report's cost column and the Pareto chart show.
struct ModelCosts {
    std::string source;
    std::string unit;
    std::map<std::string, double, std::less<>> per_model;

    std::optional<double> of(std::string_view model) const {
        const auto it = per_model.find(model);
        return it == per_model.end() ? std::nullopt : std::optional<double>(it->second);
    }
};

// A budget's mark on one material's page: the model recommended, or none (with why). Made from the fit stage's
// BudgetChoice (libfit/fit/budget.hpp, choose_model) by report_costs().
struct BudgetMark {
    std::optional<std::string> model;
    std::string note;  // "cheapest model whose worst channel meets 0.5 %", "no model meets 0.5 %"
};

// The inputs the report shows for cost and budget; every field may be empty (then the pages say so).
struct CostAndBudget {
    std::optional<ModelCosts> costs;
    std::optional<double> budget;               // worst-channel rel_rms the choice had to meet
    std::map<std::string, BudgetMark> choices;  // material id → choice
    // material id → the recommendation (export/recommendation.hpp) the material's page opens with and the heat map
    // marks; empty when none was asked for.
    std::map<std::string, Recommendation> recommendations;
};

// What the report shows for a cost table (the built-in SPIR-V op counts or a `metalfit bench --json` file) and, when
// a budget is given, each material's choose_model() result.
CostAndBudget report_costs(const std::vector<MaterialFit>& fits, const CostTable& table,
                           const std::optional<Budget>& budget);
// The same with each material's recommendation for `target` under `tolerance` (recommend(), ranked by `table`).
CostAndBudget report_costs(const std::vector<MaterialFit>& fits, const CostTable& table,
                           const std::optional<Budget>& budget, const Tolerance& tolerance, ExportFormat target);

// The same for one material: the table's costs, and its own choice and recommendation (what its entry in the report
// shows; the report written material by material, ReportStream, makes one per material).
CostAndBudget report_costs_of(const MaterialFit& fit, const CostTable& table, const std::optional<Budget>& budget,
                              const Tolerance& tolerance, ExportFormat target);

}  // namespace metalfit
