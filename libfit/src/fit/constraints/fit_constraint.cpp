#include "fit/constraints/fit_constraint.hpp"

#include <limits>

#include "fit/constraints/constraint_kinds.hpp"
#include "libfit/base/number_text.hpp"

namespace metalfit::detail {

namespace {
class Unconstrained final : public FitConstraint {};
}  // namespace

std::unique_ptr<const FitConstraint> make_fit_constraint(const FitConstraints& constraints) {
    if (constraints.pin_f0) return pinned_f0_constraint();
    if (constraints.f0_tolerance) return f0_tolerance_constraint(*constraints.f0_tolerance);
    if (constraints.gamut_fit) return unit_range_constraint();
    return std::make_unique<Unconstrained>();
}

double f0_error(double F1, double R1) { return R1 > 0 ? F1 / R1 - 1 : std::numeric_limits<double>::quiet_NaN(); }

std::string message_number(double x) { return significant_text(x, 6); }

}  // namespace metalfit::detail
