// --pin F0: F(1) = R(1) exactly in every channel (docs/fitting.md, "Constraints").
#include <cmath>
#include <optional>
#include <span>

#include "fit/constraints/constraint_kinds.hpp"

namespace metalfit::detail {

namespace {

class PinnedF0 final : public FitConstraint {
public:
    void require(const Model& model) const override {
        if (!model.can_pin_f0())
            throw UsageError("--pin F0: model " + std::string(model.id()) + " cannot hold F(1) at a given value");
    }
    ChannelConstraints channel(double R1) const override {
        ChannelConstraints c;
        c.pinned_f0 = R1;
        return c;
    }
    // The unconstrained optimum is the best start of the pinned fit (from the others alone LM stops in local minima:
    // rational on zinc, 19 % instead of 1.3 %). Where F(1) = R(1) needs a parameter outside its bounds (gold's red
    // R(1) = 1.038 asks Gulbrandsen's r > 0.99999) or no start holds it, the pin is refused for this channel and the
    // unpinned fit kept, said in fit.refused and on stderr (an export must never carry parameters outside the
    // model's own bounds).
    ConstrainedChannel fit_channel(const Model& model, const ChannelTarget& target, std::vector<NamedStart>& starts,
                                   double R1) const override {
        std::optional<ChannelFit> unpinned;
        ChannelFit free = model.fit(target, starts);
        if (!free.params.empty()) {
            starts.insert(starts.begin(), NamedStart{"unpinned optimum", free.params});
            unpinned = std::move(free);
        }
        ConstrainedChannel out{model.fit(target, starts, channel(R1)), {}, {}};
        std::string needs;
        if (out.fit.params.empty())
            needs = "parameters no start reaches inside the bounds";
        else if (const std::string bounds = outside_bounds(model, out.fit.params); !bounds.empty())
            needs = bounds;
        else if (const double F1 = model.evaluate(std::span<const double>(out.fit.params), 1.0);
                 !(std::abs(F1 - R1) <= 1e-9))
            needs = "a value the model cannot take (F(1) = " + message_number(F1) + ")";
        if (!needs.empty() && unpinned) {
            out.refused = "--pin F0 refused: F(1) = R(1) = " + message_number(R1) + " needs " + needs +
                          "; the unpinned fit is kept (F(1) = " +
                          message_number(model.evaluate(std::span<const double>(unpinned->params), 1.0)) + ")";
            out.fit = std::move(*unpinned);
        }
        return out;
    }
    // A refused pin: the unpinned fit competes with every closed form.
    bool admits(const Model& model, const ChannelParameters& params, double R1, bool refused) const override {
        return refused || std::abs(model.evaluate(std::span<const double>(params), 1.0) - R1) <= 1e-12;
    }
    std::string refused_qualifier() const override { return " with F0 pinned"; }
    // The pin computes a parameter, which the data may push out of its bounds (F0 ≥ 1 for n, k models).
    void explain(std::string& unrepresentable, const Model& model, const ChannelParameters& kept, double /*err_f0*/,
                 double R1, bool refused, const std::string& /*unmet*/) const override {
        if (refused) return;
        const std::string out = outside_bounds(model, kept);
        const double F1 = model.evaluate(std::span<const double>(kept), 1.0);
        if (!out.empty() || !(std::abs(F1 - R1) <= 1e-9))
            unrepresentable =
                "--pin F0: F(1) = R(1) = " + message_number(R1) + " needs " +
                (out.empty() ? "a value the model cannot take (F(1) = " + message_number(F1) + ")" : out) +
                ": the model cannot represent these data with F0 pinned";
    }
};

}  // namespace

std::unique_ptr<const FitConstraint> pinned_f0_constraint() { return std::make_unique<PinnedF0>(); }

}  // namespace metalfit::detail
