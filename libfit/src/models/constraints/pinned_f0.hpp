// --pin F0 in one channel's solve (internal): F(1) equals a given value exactly.
#pragma once

#include <array>

#include "models/constraints/channel_constraint.hpp"
#include "models/curve_residual.hpp"

namespace metalfit::detail {

// The curve's residuals with F(1) pinned: the pinned parameter is recomputed from the others before each evaluation
// (its own value, held constant by the solver, is ignored), so the derivatives carry the constraint.
template <class M>
struct PinnedCurveResidual {
    const ChannelTarget* target;
    double F0;

    template <class T>
    bool operator()(const T* params, T* residuals) const {
        std::array<T, M::kParameters.size()> q;
        for (std::size_t i = 0; i < q.size(); ++i) q[i] = params[i];
        q[M::kPinnedParameter] = M::pinned_value(q.data(), T(F0));
        return CurveResidual<M>{target}(q.data(), residuals);
    }
};

// The model's pinned parameter (kPinnedParameter) held by the solver and computed from the others and F0.
template <class M>
class PinnedF0 final : public ChannelConstraint {
public:
    static constexpr int kCount = static_cast<int>(M::kParameters.size());
    explicit PinnedF0(double F0) : F0_(F0) {}

    ceres::CostFunction* curve_residual(const ChannelTarget& target) const override {
        return new ceres::AutoDiffCostFunction<PinnedCurveResidual<M>, ceres::DYNAMIC, kCount>(
            new PinnedCurveResidual<M>{&target, F0_}, static_cast<int>(target.mu.size()));
    }
    int held_parameter() const override { return static_cast<int>(M::kPinnedParameter); }
    bool keeps_projection() const override { return false; }
    bool keeps_start_pruning() const override { return false; }
    void finish(ChannelParameters& x) const override { x[M::kPinnedParameter] = M::pinned_value(x.data(), F0_); }

private:
    double F0_;
};

}  // namespace metalfit::detail
