// The cheapest model for an error budget: given a material's fits of several models, a cost table and a budget on
// one metric, the model of lowest cost whose fit meets the budget in every channel, or none with the reason of each
// model. `metalfit fit --budget`, `metalfit export --model best:BUDGET` and the report call choose_model().
#pragma once

#include <functional>
#include <optional>
#include <string>
#include <vector>

#include "libfit/base/enum_names.hpp"
#include "libfit/fit/fit.hpp"
#include "libfit/fit/model_cost.hpp"

namespace metalfit {

// The metric a budget bounds: the worst channel's rel_rms, max_rel or |err_f0| (fractions), or the worst ΔE2000 (units
// of ΔE).
enum class BudgetMetric { rel_rms, max_rel, de2000_max, f0_err };
inline constexpr EnumNames kBudgetMetricNames{"budget metric", KnownNamesWording::known,
                                              std::array{EnumName<BudgetMetric>{BudgetMetric::rel_rms, "rel_rms"},
                                                         EnumName<BudgetMetric>{BudgetMetric::max_rel, "max_rel"},
                                                         EnumName<BudgetMetric>{BudgetMetric::de2000_max, "de2000_max"},
                                                         EnumName<BudgetMetric>{BudgetMetric::f0_err, "f0_err"}}};
std::string to_string(BudgetMetric metric);
BudgetMetric parse_budget_metric(const std::string& text);  // "rel_rms" | "max_rel" | "de2000_max", else UsageError

struct Budget {
    double limit = 0;  // a fraction for rel_rms / max_rel (0.005 = 0.5 %), ΔE units for de2000_max
    BudgetMetric metric = BudgetMetric::rel_rms;
};
// "0.5%" (a percentage) or "0.005" (a fraction) for rel_rms / max_rel; a plain number ("1.0") for de2000_max (a "%"
// is then a UsageError). Non-finite or negative limits are UsageErrors.
Budget parse_budget(const std::string& text, BudgetMetric metric);
// A limit given as a fraction: "0.5%" (a percentage) or "0.005". Else a UsageError naming `option` ("--f0-tolerance
// '-1': give a number >= 0, e.g. 0.5% or 0.005").
double parse_fraction_limit(const std::string& option, const std::string& text);
// "rel_rms <= 0.5 %" or "de2000_max <= 1"
std::string budget_text(const Budget& budget);

// The value of the budget's metric for a fit: max over R, G, B for rel_rms / max_rel / |err_f0| (NaN if any is
// undefined), the worst ΔE2000 otherwise.
double budget_value(const Metrics& metrics, BudgetMetric metric);
// The channel (0, 1, 2) that gives budget_value, or -1 for de2000_max (not per channel) or an undefined value.
int budget_channel(const Metrics& metrics, BudgetMetric metric);

// Several limits met together (a tolerance: rel_rms, F0 error and ΔE2000 at once); the first is the one a single-budget
// caller gave.
using Budgets = std::vector<Budget>;

struct BudgetCandidate {
    const Model* model = nullptr;
    std::optional<double> cost;  // empty: the table has no cost for it
    double value = 0;            // budget_value of its fit for the first budget
    std::vector<double> values;  // budget_value for every budget, in their order
    bool qualifies = false;      // allowed, cost known and every value <= its limit
    // Why it does not qualify ("" when it does): every limit it misses, by how much and in which channel
    // ("rel_rms 0.84 % > 0.5 % (G, by 0.34 %); f0_err 0.7 % > 0.5 % (R, by 0.2 %)"), or the target's or the cost
    // table's reason.
    std::string reason;
};

struct BudgetChoice {
    Budget budget;            // the first of budgets
    Budgets budgets;          // every limit the chosen model meets
    std::string cost_source;  // CostTable::source
    std::string cost_unit;
    // Every model of the input, cheapest first (ties: the lower value, then the input's order); models without a cost
    // last, in the input's order.
    std::vector<BudgetCandidate> candidates;
    // The chosen model: the first qualifying candidate; nullptr when none qualifies.
    const Model* chosen = nullptr;

    // One line: "schlick-comp-linear (21 SPIR-V ops, rel_rms 0.43 %)" or "none qualifies: best rel_rms is rational's
    // 0.78 %".
    std::string summary() const;
};

// Chooses among `results` (one material's ModelResults, e.g. MaterialFit::models).
BudgetChoice choose_model(const std::vector<ModelResult>& results, const CostTable& costs, const Budget& budget);

// Which models a consumer can use: "" when `model` is allowed, else why not (the recommendation's --target).
using ModelFilter = std::function<std::string(const Model& model)>;
// The one definition of "the cheapest model meeting a tolerance": every budget met, the model allowed by `allowed`
// (null: every model), ordered as above by cost, then the first budget's value.
BudgetChoice choose_model(const std::vector<ModelResult>& results, const CostTable& costs, const Budgets& budgets,
                          const ModelFilter& allowed);

}  // namespace metalfit
