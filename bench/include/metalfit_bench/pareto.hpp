// The Pareto front of cost against error: a row is on the front when no other row is both at least as fast and at
// least as accurate, and better in one of the two. Measured times are noisy and fitted errors can tie (schlick and
// lazanyi fit the same curve wherever F0 < 1), so both comparisons have a tolerance: two costs within a factor
// (1 + cost_tolerance) are a tie, and two errors within error_tolerance (relative) or error_floor (absolute).
#pragma once

#include <span>
#include <vector>

namespace metalfit::bench {

struct ParetoPoint {
    double cost = 0;   // e.g. ns per evaluation, or a ratio to a baseline
    double error = 0;  // e.g. catalog median rel_rms
};

struct ParetoTolerance {
    double cost = 0.10;         // 10 %: beyond the noise of a ratio measured on a shared machine
    double error = 0.05;        // 5 %
    double error_floor = 1e-5;  // 0.001 % rel_rms
};

// true when `a` dominates `b` (better or tied in both, strictly better beyond the tolerance in one).
bool dominates(const ParetoPoint& a, const ParetoPoint& b, const ParetoTolerance& tolerance = {});

// For each point, whether it is on the front (not dominated by any other). Points with a NaN coordinate are never
// on the front and dominate nothing.
std::vector<bool> pareto_front(std::span<const ParetoPoint> points, const ParetoTolerance& tolerance = {});

}  // namespace metalfit::bench
