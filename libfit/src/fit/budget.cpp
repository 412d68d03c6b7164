#include "libfit/fit/budget.hpp"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <numeric>
#include <stdexcept>

#include "libfit/base/errors.hpp"
#include "libfit/base/number_text.hpp"

namespace metalfit {

namespace {

std::string number(double x, int digits = 3) { return significant_text(x, digits); }

PerChannel absolute(PerChannel v) {
    for (double& x : v) x = std::abs(x);
    return v;
}

bool is_fraction(BudgetMetric metric) { return metric != BudgetMetric::de2000_max; }

std::string value_text(double value, BudgetMetric metric) {
    if (std::isnan(value)) return "undefined";
    return is_fraction(metric) ? number(100 * value) + " %" : number(value);
}

}  // namespace

std::string to_string(BudgetMetric metric) { return std::string(kBudgetMetricNames.name(metric)); }

BudgetMetric parse_budget_metric(const std::string& text) { return kBudgetMetricNames.parse(text); }

Budget parse_budget(const std::string& text, BudgetMetric metric) {
    const bool percent = !text.empty() && text.back() == '%';
    const std::string digits = percent ? text.substr(0, text.size() - 1) : text;
    char* end = nullptr;
    const double value = digits.empty() ? std::nan("") : std::strtod(digits.c_str(), &end);
    if (digits.empty() || end != digits.c_str() + digits.size() || !std::isfinite(value) || value < 0)
        throw UsageError("budget '" + text +
                         "': give a non-negative number, e.g. 0.5% or 0.005 (or 1.0 for de2000_max)");
    if (percent && !is_fraction(metric))
        throw UsageError("budget '" + text +
                         "': de2000_max is in units of Delta E, not a percentage (e.g. --budget 1.0)");
    return {percent ? value / 100 : value, metric};
}

double parse_fraction_limit(const std::string& option, const std::string& text) {
    const bool percent = !text.empty() && text.back() == '%';
    const std::string digits = percent ? text.substr(0, text.size() - 1) : text;
    char* end = nullptr;
    const double value = digits.empty() ? std::nan("") : std::strtod(digits.c_str(), &end);
    if (digits.empty() || end != digits.c_str() + digits.size() || !std::isfinite(value) || value < 0)
        throw UsageError(option + " '" + text + "': give a number >= 0, e.g. 0.5% or 0.005");
    return percent ? value / 100 : value;
}

std::string budget_text(const Budget& budget) {
    return to_string(budget.metric) + " <= " + value_text(budget.limit, budget.metric);
}

double budget_value(const Metrics& metrics, BudgetMetric metric) {
    switch (metric) {
        case BudgetMetric::rel_rms: return worst_channel(metrics.rel_rms);
        case BudgetMetric::max_rel: return worst_channel(metrics.max_rel);
        case BudgetMetric::de2000_max: return metrics.de2000_max;
        case BudgetMetric::f0_err: return worst_channel(absolute(metrics.err_f0));
    }
    return std::nan("");
}

int budget_channel(const Metrics& metrics, BudgetMetric metric) {
    PerChannel v{};
    switch (metric) {
        case BudgetMetric::rel_rms: v = metrics.rel_rms; break;
        case BudgetMetric::max_rel: v = metrics.max_rel; break;
        case BudgetMetric::f0_err: v = absolute(metrics.err_f0); break;
        case BudgetMetric::de2000_max: return -1;
    }
    if (std::isnan(worst_channel(v))) return -1;
    return static_cast<int>(std::max_element(v.begin(), v.end()) - v.begin());
}

std::string BudgetChoice::summary() const {
    const auto cost_text = [&](const BudgetCandidate& c) {
        return c.cost ? number(*c.cost, 4) + " " + cost_unit : std::string("no cost");
    };
    if (chosen) {
        for (const BudgetCandidate& c : candidates)
            if (c.model == chosen)
                return std::string(chosen->id()) + " (" + cost_text(c) + ", " + to_string(budget.metric) + " " +
                       value_text(c.value, budget.metric) + ")";
    }
    const BudgetCandidate* best = nullptr;
    for (const BudgetCandidate& c : candidates)
        if (!std::isnan(c.value) && (!best || c.value < best->value)) best = &c;
    if (!best) return "none qualifies: no model has a defined " + to_string(budget.metric);
    return "none qualifies: the lowest " + to_string(budget.metric) + " is " + std::string(best->model->id()) + "'s " +
           value_text(best->value, budget.metric) + (best->cost ? "" : " (and it has no cost in the table)");
}

BudgetChoice choose_model(const std::vector<ModelResult>& results, const CostTable& costs, const Budget& budget) {
    return choose_model(results, costs, Budgets{budget}, nullptr);
}

BudgetChoice choose_model(const std::vector<ModelResult>& results, const CostTable& costs, const Budgets& budgets,
                          const ModelFilter& allowed) {
    if (budgets.empty()) throw std::logic_error("choose_model: no budget");
    BudgetChoice choice{budgets.front(), budgets, costs.source, costs.unit, {}, nullptr};
    for (const ModelResult& r : results) {
        BudgetCandidate c;
        c.model = r.model;
        c.cost = costs.cost_of(r.model->id());
        const Metrics& m = r.fit.value.metrics;
        for (const Budget& b : budgets) c.values.push_back(budget_value(m, b.metric));
        c.value = c.values.front();
        const std::string refused = allowed ? allowed(*r.model) : std::string();
        if (!refused.empty())
            c.reason = refused;
        else if (!c.cost)
            c.reason = "no cost for " + std::string(r.model->id()) + " in " + costs.source;
        else
            for (std::size_t i = 0; i < budgets.size(); ++i) {
                const Budget& b = budgets[i];
                const double v = c.values[i];
                std::string miss;
                if (std::isnan(v))
                    miss = to_string(b.metric) + " undefined";
                else if (!(v <= b.limit)) {
                    const int channel = budget_channel(m, b.metric);
                    miss = to_string(b.metric) + " " + value_text(v, b.metric) + " > " + value_text(b.limit, b.metric) +
                           " (" + (channel >= 0 ? std::string(1, "RGB"[channel]) + ", " : std::string()) + "by " +
                           value_text(v - b.limit, b.metric) + ")";
                }
                if (!miss.empty()) c.reason += (c.reason.empty() ? "" : "; ") + miss;
            }
        c.qualifies = c.reason.empty();
        choice.candidates.push_back(std::move(c));
    }
    // Cheapest first; ties by the lower value, then the input order (stable); no cost last.
    std::stable_sort(choice.candidates.begin(), choice.candidates.end(),
                     [](const BudgetCandidate& x, const BudgetCandidate& y) {
                         if (x.cost.has_value() != y.cost.has_value()) return x.cost.has_value();
                         if (!x.cost) return false;
                         if (*x.cost != *y.cost) return *x.cost < *y.cost;
                         const bool xn = std::isnan(x.value), yn = std::isnan(y.value);
                         if (xn != yn) return yn;
                         return !xn && x.value < y.value;
                     });
    for (const BudgetCandidate& c : choice.candidates)
        if (c.qualifies) {
            choice.chosen = c.model;
            break;
        }
    return choice;
}

}  // namespace metalfit
