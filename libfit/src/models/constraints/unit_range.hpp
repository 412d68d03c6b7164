// --gamut-fit in one channel's solve (internal): the curve stays in [0, 1] at every μ of a 4097-point grid.
#pragma once

#include <algorithm>
#include <cmath>

#include "models/constraints/channel_constraint.hpp"

namespace metalfit::detail {

// The penalty's state during one solve: its weight grows and its upper end tightens between solves of the same
// problem.
struct GamutLimits {
    static constexpr int kGrid = 4097;  // the grid --gamut-fit is checked on (gamut_excess)
    double weight = 0;                  // 0 and stride kGrid: the first solve is the unconstrained one
    double upper = 1;
    int stride = kGrid;  // every stride-th point: 257 while the penalty stiffens, then every point
};

// weight · (how far M(p, μ_j) is outside [0, upper]) on the uniform grid of μ the constraint is checked on, zero
// inside.
template <class M>
struct GamutPenalty {
    const GamutLimits* limits;

    template <class T>
    bool operator()(const T* params, T* residuals) const {
        for (int j = 0; j < GamutLimits::kGrid; ++j) {
            if (j % limits->stride != 0) {
                residuals[j] = T(0);
                continue;
            }
            const T F = M::evaluate(params, T(static_cast<double>(j) / (GamutLimits::kGrid - 1)));
            const T w(limits->weight);
            residuals[j] = F > T(limits->upper) ? w * (F - T(limits->upper)) : (F < T(0) ? -w * F : T(0));
        }
        return true;
    }
};

// The largest excursion of the curve outside [0, 1] on a 4097-point grid (0 inside): what --gamut-fit guarantees.
// At μ = 0 every model's F = 1 by construction, which may round to 1 + 1 ulp: there 1e-15 is allowed.
inline constexpr double kGamutTolerance = 0;
template <class M>
double gamut_excess(const ChannelParameters& p) {
    double excess = std::max(0.0, std::abs(M::evaluate(p.data(), 0.0) - 1) - 1e-15);
    for (int j = 1; j <= 4096; ++j) {
        const double F = M::evaluate(p.data(), j / 4096.0);
        excess = std::max({excess, F - 1, -F});
    }
    return excess;
}

// The penalty block beside the curve's, zero while the solution holds; after the plain solve, where the solution
// leaves [0, 1]: continuation, a stiffer penalty from the last solution, then the upper end lowered by what is still
// outside until the 4097-point grid holds the curve. The cost a start is compared on is the penalty-free curve cost
// (the weight is 0 again at the end).
template <class M>
class UnitRange final : public ChannelConstraint {
public:
    static constexpr int kCount = static_cast<int>(M::kParameters.size());

    void add_residuals(ceres::Problem& problem, double* x) const override {
        limits_ = GamutLimits{};
        problem.AddResidualBlock(
            new ceres::AutoDiffCostFunction<GamutPenalty<M>, GamutLimits::kGrid, kCount>(new GamutPenalty<M>{&limits_}),
            nullptr, x);
    }
    bool keeps_projection() const override { return false; }
    bool keeps_start_pruning() const override { return false; }
    bool after_solve(ceres::Problem& problem, const ceres::Solver::Options& options, ChannelParameters& x,
                     ceres::Solver::Summary& summary) const override {
        const double initial_cost = summary.initial_cost;
        if (gamut_excess<M>(x) > kGamutTolerance) {  // else the unconstrained optimum of this start holds already
            limits_.stride = 16;
            for (const double weight : {1e2, 1e4, 1e6}) {
                limits_.weight = weight;
                ceres::Solve(options, &problem, &summary);
            }
        }
        limits_.stride = 1;
        for (int round = 0; round < 8; ++round) {
            const double excess = gamut_excess<M>(x);
            if (!(excess > kGamutTolerance)) break;
            limits_.upper -= 2 * excess + 1e-12;
            ceres::Solve(options, &problem, &summary);
        }
        summary.initial_cost = initial_cost;
        if (!(gamut_excess<M>(x) <= kGamutTolerance)) return false;  // this start cannot hold it
        limits_.weight = 0;
        return true;
    }

private:
    mutable GamutLimits limits_;  // of the problem being solved (add_residuals to after_solve)
};

}  // namespace metalfit::detail
