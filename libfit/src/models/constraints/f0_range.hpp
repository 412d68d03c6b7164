// --f0-tolerance in one channel's solve (internal): F(1) within an interval, a true constraint.
#pragma once

#include <algorithm>
#include <array>

#include "models/constraints/channel_constraint.hpp"
#include "models/curve_residual.hpp"

namespace metalfit::detail {

// F(1) is an unknown of the solve held in the pinned parameter's slot of the parameter block, bounded to the
// interval; the pinned parameter is recomputed from the others and that F(1) before each evaluation (as
// PinnedCurveResidual), so the solve is the bounded least squares of the reparameterised curve: a true optimum
// under |F(1)/R(1) − 1| ≤ T, not a penalty. Where the computed parameter leaves its own bounds the evaluation fails,
// which Ceres treats as an infeasible step (it shrinks the trust region): the solve stays inside the model's bounds.
template <class M>
struct F0RangeResidual {
    const ChannelTarget* target;

    template <class T>
    bool operator()(const T* params, T* residuals) const {
        std::array<T, M::kParameters.size()> q;
        for (std::size_t i = 0; i < q.size(); ++i) q[i] = params[i];
        q[M::kPinnedParameter] = M::pinned_value(q.data(), params[M::kPinnedParameter]);
        const Parameter& bounds = M::kParameters[M::kPinnedParameter];
        if (!(q[M::kPinnedParameter] >= T(bounds.lower) && q[M::kPinnedParameter] <= T(bounds.upper))) return false;
        return CurveResidual<M>{target}(q.data(), residuals);
    }
};

template <class M>
class F0Range final : public ChannelConstraint {
public:
    static constexpr int kCount = static_cast<int>(M::kParameters.size());
    static constexpr int kSlot = static_cast<int>(M::kPinnedParameter);  // holds F(1) during the solves
    explicit F0Range(std::array<double, 2> range) : range_(range) {}

    ceres::CostFunction* curve_residual(const ChannelTarget& target) const override {
        return new ceres::AutoDiffCostFunction<F0RangeResidual<M>, ceres::DYNAMIC, kCount>(
            new F0RangeResidual<M>{&target}, static_cast<int>(target.mu.size()));
    }
    std::optional<std::array<double, 2>> bounds(int i) const override {
        return i == kSlot ? std::optional(range_) : std::nullopt;
    }
    bool keeps_projection() const override { return false; }
    bool keeps_start_pruning() const override { return false; }
    void prepare_start(ChannelParameters& x) const override {
        x[kSlot] = std::clamp(M::evaluate(x.data(), 1.0), range_[0], range_[1]);
    }
    void finish(ChannelParameters& x) const override { x[kSlot] = M::pinned_value(x.data(), x[kSlot]); }

private:
    std::array<double, 2> range_;
};

}  // namespace metalfit::detail
