#include "libfit/report/model_costs.hpp"

namespace metalfit {
namespace {

BudgetMark budget_mark(const MaterialFit& fit, const CostTable& table, const Budget& budget) {
    const BudgetChoice choice = choose_model(fit.models, table, budget);
    BudgetMark mark;
    if (choice.chosen) mark.model = std::string(choice.chosen->id());
    mark.note = (choice.chosen ? "cheapest model meeting " + budget_text(budget) + ": " : budget_text(budget) + ": ") +
                choice.summary();
    return mark;
}

}  // namespace

CostAndBudget report_costs(const std::vector<MaterialFit>& fits, const CostTable& table,
                           const std::optional<Budget>& budget) {
    CostAndBudget out;
    ModelCosts costs{table.source, table.unit, {}};
    for (const ModelCost& c : table.costs) costs.per_model.emplace(c.model, c.cost);
    out.costs = std::move(costs);
    if (!budget) return out;
    out.budget = budget->limit;
    for (const MaterialFit& fit : fits) {
        out.choices[fit.material.id] = budget_mark(fit, table, *budget);
    }
    return out;
}

CostAndBudget report_costs(const std::vector<MaterialFit>& fits, const CostTable& table,
                           const std::optional<Budget>& budget, const Tolerance& tolerance, ExportFormat target) {
    CostAndBudget out = report_costs(fits, table, budget);
    for (const MaterialFit& fit : fits)
        out.recommendations.emplace(fit.material.id, recommend(fit, table, tolerance, target));
    return out;
}

CostAndBudget report_costs_of(const MaterialFit& fit, const CostTable& table, const std::optional<Budget>& budget,
                              const Tolerance& tolerance, ExportFormat target) {
    CostAndBudget out = report_costs({}, table, budget);
    if (budget) {
        out.choices[fit.material.id] = budget_mark(fit, table, *budget);
    }
    out.recommendations.emplace(fit.material.id, recommend(fit, table, tolerance, target));
    return out;
}

}  // namespace metalfit
