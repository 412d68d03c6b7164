// A constraint of a model's fit to a target (internal: fit_model composes the active one instead of a branch per
// constraint; FitConstraints::check_combination says which combine, and none does today). Each says what it asks of
// a channel's solve (ChannelConstraints, which the model's fit_channel composes from models/constraints/), how a
// channel is fitted under it (the unconstrained optimum first, kept where it meets the constraint or where the
// constrained solution is out of the model's reach), whether a closed form meets it (only those compete as
// fallbacks), and what the record says where the data cannot meet it. docs/fitting.md, "Targets and constraints".
#pragma once

#include <memory>
#include <string>
#include <vector>

#include "libfit/fit/fit.hpp"
#include "libfit/models/model.hpp"

namespace metalfit::detail {

// One channel fitted under a constraint.
struct ConstrainedChannel {
    ChannelFit fit;
    std::string refused;  // the constraint refused for this channel and what was kept instead (FitResult::refused)
    std::string unmet;    // why the constrained solution was not kept, for fit.unrepresentable ("" when it was)
};

class FitConstraint {
public:
    virtual ~FitConstraint() = default;

    // UsageError where the model cannot be fitted under the constraint at all.
    virtual void require(const Model& /*model*/) const {}
    // What the constraint asks of the solve of one channel whose R(1) is R1.
    virtual ChannelConstraints channel(double /*R1*/) const { return {}; }
    // One channel fitted from `starts`, which the constraint may extend (the unconstrained optimum as the first).
    virtual ConstrainedChannel fit_channel(const Model& model, const ChannelTarget& target,
                                           std::vector<NamedStart>& starts, double R1) const {
        return {model.fit(target, starts, channel(R1)), {}, {}};
    }
    // Whether a channel's parameters (a closed form's) meet the constraint: only those compete as the fit's fallback.
    // `refused`: the constraint was refused for that channel (its unconstrained fit kept).
    virtual bool admits(const Model& /*model*/, const ChannelParameters& /*params*/, double /*R1*/,
                        bool /*refused*/) const {
        return true;
    }
    // Where every start ended on parameters that are no curve: whether the first start that is one may be kept as it
    // is (a start need not meet the constraint), and what the error says otherwise.
    virtual bool keeps_a_start_as_is() const { return true; }
    virtual std::string unsolved_qualifier() const { return {}; }  // " inside [0, 1] (--gamut-fit)"
    // fit.unrepresentable of a channel: after the refusal's sentence (which ends with refused_qualifier()), what the
    // constraint adds or says instead where the kept parameters do not meet it.
    virtual std::string refused_qualifier() const { return {}; }  // " with F0 pinned"
    virtual void explain(std::string& /*unrepresentable*/, const Model& /*model*/, const ChannelParameters& /*kept*/,
                         double /*err_f0*/, double /*R1*/, bool /*refused*/, const std::string& /*unmet*/) const {}
};

// The active constraint of `constraints` (which check_combination has passed); without any, the plain fit.
std::unique_ptr<const FitConstraint> make_fit_constraint(const FitConstraints& constraints);

// err_f0 of docs/fitting.md: F(1) / R(1) − 1, NaN where R(1) ≤ 0.
double f0_error(double F1, double R1);
// significant_text(x, 6): the numbers of the constraints' messages.
std::string message_number(double x);

}  // namespace metalfit::detail
