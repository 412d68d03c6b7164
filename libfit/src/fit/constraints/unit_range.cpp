// --gamut-fit: every channel's fitted curve stays in [0, 1] at every μ of a 4097-point grid (docs/fitting.md,
// "Constraints").
#include "fit/constraints/constraint_kinds.hpp"

namespace metalfit::detail {

namespace {

class UnitRange final : public FitConstraint {
public:
    ChannelConstraints channel(double /*R1*/) const override {
        ChannelConstraints c;
        c.unit_range = true;
        return c;
    }
    // The grid the solve holds (its post-check, models/constraints/unit_range.hpp) checked here through the runtime
    // model: closed forms outside [0, 1] never compete.
    bool admits(const Model& model, const ChannelParameters& params, double /*R1*/, bool /*refused*/) const override {
        return curve_excess_outside_unit_range(model, params) == 0;
    }
    // A start kept as it is need not lie in [0, 1]: a channel no start solves inside it is an error.
    bool keeps_a_start_as_is() const override { return false; }
    std::string unsolved_qualifier() const override { return " inside [0, 1] (--gamut-fit)"; }
};

}  // namespace

std::unique_ptr<const FitConstraint> unit_range_constraint() { return std::make_unique<UnitRange>(); }

}  // namespace metalfit::detail
