// --f0-tolerance T: |err_f0| ≤ T in every channel, a constraint of the solve (docs/fitting.md, "Constraints").
#include <array>
#include <cmath>
#include <optional>
#include <span>

#include "fit/constraints/constraint_kinds.hpp"

namespace metalfit::detail {

namespace {

class F0Tolerance final : public FitConstraint {
public:
    explicit F0Tolerance(double T) : T_(T) {}

    void require(const Model& model) const override {
        if (!model.can_pin_f0())
            throw UsageError("--pin F0: model " + std::string(model.id()) + " cannot hold F(1) at a given value");
    }
    // F(1) a bounded unknown of the solve, a hair inside the interval, so that the F(1) computed back from the
    // parameters stays within T.
    ChannelConstraints channel(double R1) const override {
        ChannelConstraints c;
        const double t = T_ * (1 - 1e-9);
        c.f0_range = std::array<double, 2>{R1 * (1 - t), R1 * (1 + t)};
        return c;
    }
    // A channel whose unconstrained optimum meets the tolerance keeps it (the constrained optimum cannot be lower);
    // else F(1) is a bounded unknown, from the unconstrained optimum first and every start. The parameter computed
    // from F(1) may need a value outside its bounds (gold's red R(1) = 1.038 in Linear Rec.709 asks Gulbrandsen's
    // r > 1): such parameters are never kept; the unconstrained fit stays, and the record says that the model cannot
    // meet the tolerance. Where R(1) ≤ 0 the tolerance has no meaning: the plain fit.
    ConstrainedChannel fit_channel(const Model& model, const ChannelTarget& target, std::vector<NamedStart>& starts,
                                   double R1) const override {
        if (!(R1 > 0)) return {model.fit(target, starts, ChannelConstraints{}), {}, {}};
        ChannelFit free = model.fit(target, starts);
        if (!free.params.empty() && meets(model, free.params, R1, 1)) return {std::move(free), {}, {}};
        std::optional<ChannelFit> free_fit;
        if (!free.params.empty()) {
            starts.insert(starts.begin(), NamedStart{"unconstrained optimum", free.params});
            free_fit = std::move(free);
        }
        ConstrainedChannel out{model.fit(target, starts, channel(R1)), {}, {}};
        if (!free_fit) return out;
        if (out.fit.params.empty())
            out.unmet = "a parameter outside its bounds from every start";
        else if (const std::string bounds = outside_bounds(model, out.fit.params); !bounds.empty())
            out.unmet = bounds;
        else if (!meets(model, out.fit.params, R1, 1 + 1e-9))
            out.unmet = "an F(1) the model cannot take";  // lazanyi's k from n where R(1) > 1
        if (!out.unmet.empty()) out.fit = std::move(*free_fit);
        return out;
    }
    bool admits(const Model& model, const ChannelParameters& params, double R1, bool /*refused*/) const override {
        return R1 > 0 ? meets(model, params, R1, 1) : true;
    }
    // The F(1) within the tolerance computes a parameter too, which may need a value outside its bounds.
    void explain(std::string& unrepresentable, const Model& /*model*/, const ChannelParameters& /*kept*/, double err_f0,
                 double /*R1*/, bool /*refused*/, const std::string& unmet) const override {
        if (unmet.empty() && !(std::abs(err_f0) > T_)) return;
        unrepresentable =
            "--f0-tolerance " + message_number(T_) + ": err_f0 = " + message_number(err_f0) +
            (unmet.empty() ? std::string()
                           : " (the constrained fit needs " + unmet + "; the unconstrained fit is kept)") +
            ": the model cannot represent these data within the F0 tolerance";
    }

private:
    // |err_f0| within T times `slack`.
    bool meets(const Model& model, const ChannelParameters& params, double R1, double slack) const {
        return std::abs(f0_error(model.evaluate(std::span<const double>(params), 1.0), R1)) <= T_ * slack;
    }
    double T_;
};

}  // namespace

std::unique_ptr<const FitConstraint> f0_tolerance_constraint(double T) { return std::make_unique<F0Tolerance>(T); }

}  // namespace metalfit::detail
