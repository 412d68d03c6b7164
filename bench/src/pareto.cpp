#include "metalfit_bench/pareto.hpp"

#include <algorithm>
#include <cmath>

namespace metalfit::bench {
namespace {

bool valid(const ParetoPoint& p) { return !std::isnan(p.cost) && !std::isnan(p.error); }

}  // namespace

bool dominates(const ParetoPoint& a, const ParetoPoint& b, const ParetoTolerance& t) {
    if (!valid(a) || !valid(b)) return false;
    const double error_slack = std::max(t.error * std::max(a.error, b.error), t.error_floor);
    const bool cost_not_worse = a.cost <= b.cost * (1 + t.cost);
    const bool cost_better = a.cost * (1 + t.cost) < b.cost;
    const bool error_not_worse = a.error <= b.error + error_slack;
    const bool error_better = a.error + error_slack < b.error;
    return cost_not_worse && error_not_worse && (cost_better || error_better);
}

std::vector<bool> pareto_front(std::span<const ParetoPoint> points, const ParetoTolerance& t) {
    std::vector<bool> front(points.size(), false);
    for (std::size_t i = 0; i < points.size(); ++i) {
        if (!valid(points[i])) continue;
        front[i] = std::none_of(points.begin(), points.end(),
                                [&](const ParetoPoint& p) { return dominates(p, points[i], t); });
    }
    return front;
}

}  // namespace metalfit::bench
