// The kinds of FitConstraint (internal), each defined in its own source beside this header; make_fit_constraint
// (fit_constraint.cpp) picks the active one.
#pragma once

#include <memory>

#include "fit/constraints/fit_constraint.hpp"
#include "libfit/base/errors.hpp"

namespace metalfit::detail {

std::unique_ptr<const FitConstraint> pinned_f0_constraint();             // --pin F0 (pinned_f0.cpp)
std::unique_ptr<const FitConstraint> f0_tolerance_constraint(double T);  // --f0-tolerance T (f0_tolerance.cpp)
std::unique_ptr<const FitConstraint> unit_range_constraint();            // --gamut-fit (unit_range.cpp)

}  // namespace metalfit::detail
