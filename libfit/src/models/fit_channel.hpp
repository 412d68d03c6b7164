// Ceres least squares of one channel of one model (internal: the model adapters in model.cpp instantiate it for every
// registered model), under the active constraints composed by ConstraintSet (models/constraints/: --pin F0,
// --f0-tolerance, --gamut-fit), which say what each does to the solve; nothing here branches on a constraint.
#pragma once

#include <ceres/ceres.h>

#include <algorithm>
#include <array>
#include <bit>
#include <cmath>
#include <concepts>
#include <cstdint>
#include <limits>
#include <span>
#include <stdexcept>
#include <string>

#include "libfit/base/bounded_levenberg_marquardt.hpp"
#include "libfit/base/line_minimum.hpp"
#include "libfit/models/model.hpp"
#include "libfit/models/model_math.hpp"
#include "libfit/models/registry.hpp"
#include "models/constraints/constraint_set.hpp"
#include "models/curve_residual.hpp"
#include <vector>

namespace metalfit::detail {

// CurveResidual with the model's analytic gradient (AnalyticGradient) as the Jacobian: the same residuals and
// derivatives as autodiff (residual-only evaluations through evaluate<double>, as AutoDiffCostFunction does; those
// with a Jacobian through evaluate_with_gradient, the Jets' operations), at a fraction of the cost where the curve
// takes powers with free exponents.
template <class M>
class AnalyticCurveResidual final : public ceres::CostFunction {
public:
    static constexpr int kCount = static_cast<int>(M::kParameters.size());
    explicit AnalyticCurveResidual(const ChannelTarget* target) : target_(target) {
        set_num_residuals(static_cast<int>(target->mu.size()));
        mutable_parameter_block_sizes()->push_back(kCount);
        nodes_.reserve(target->mu.size());
        for (double mu : target->mu) nodes_.push_back(model_math::CurveNode::at(mu));
    }
    bool Evaluate(double const* const* parameters, double* residuals, double** jacobians) const override {
        const double* p = parameters[0];
        const auto n = target_->mu.size();
        if (!jacobians) {
            for (std::size_t i = 0; i < n; ++i)
                residuals[i] = target_->scale[i] * (M::evaluate(p, target_->mu[i]) - target_->value[i]);
            return true;
        }
        double gradient[kCount];
        for (std::size_t i = 0; i < n; ++i) {
            const double s = target_->scale[i];
            residuals[i] = s * (M::evaluate_with_gradient(p, nodes_[i], gradient) - target_->value[i]);
            if (jacobians[0])
                for (int j = 0; j < kCount; ++j) jacobians[0][i * kCount + j] = s * gradient[j];
        }
        return true;
    }

private:
    const ChannelTarget* target_;
    std::vector<model_math::CurveNode> nodes_;
};

template <class M>
ChannelParameters clamp_to_bounds(ChannelParameters p) {
    for (std::size_t i = 0; i < M::kParameters.size(); ++i)
        p[i] = std::clamp(p[i], M::kParameters[i].lower, M::kParameters[i].upper);
    return p;
}

// Start pruning of the plain fits (where every active constraint keeps it: none does today): a start whose cost after kIteration iterations of
// Levenberg–Marquardt is still above kFactor × the best final cost of the starts before it is abandoned. This is a
// rule measured on the catalog's solver traces, not a bound: there the starts it abandons end in other valleys or
// at the same optimum reached a few ulps higher (then a record's rel_rms moves by ≤ 3.5e-12 relative), and it
// saves 52 % of schlick-comp-general's iterations, 59 % of lazanyi-comp's, 21 % of rational's (docs/fitting.md,
// "Fit cost"); the FitOptimum tests hold the results to the independent optimum on the catalog and its alternate files.
class StartPruning final : public ceres::IterationCallback {
public:
    static constexpr int kIteration = 5;
    static constexpr double kFactor = 3.0;
    explicit StartPruning(double best_final_cost) : best_(best_final_cost) {}
    ceres::CallbackReturnType operator()(const ceres::IterationSummary& s) override {
        if (s.iteration != kIteration || !(s.cost > kFactor * best_)) return ceres::SOLVER_CONTINUE;
        pruned_ = true;
        return ceres::SOLVER_ABORT;
    }
    bool pruned() const { return pruned_; }

private:
    double best_;
    bool pruned_ = false;
};

// Models fitted by variable projection (M::Projection, e.g. LazanyiComp): the linear parameters are solved exactly
// for given non-linear ones (Projection::kNonlinearParameters, none, one or two); with one, the projected cost is
// minimised in it by line_minimum (Projection::at gives the cost and its derivative); with two, the projected
// residuals by bounded_levenberg_marquardt (Projection(z, r, J) gives them and Kaufman's Jacobian). The Projection
// gives the full parameters at its solution.
template <class M>
concept ProjectedFit = requires(typename M::Projection& p, const double* z, const ChannelParameters& start) {
    { M::Projection::kNonlinearParameters.size() } -> std::convertible_to<std::size_t>;
    { p.residuals() } -> std::convertible_to<std::size_t>;
    { p.parameters(z, start) } -> std::same_as<ChannelParameters>;
};

// ½ Σ rᵢ² of the full parameters on the target: what the projected fits compare and keep.
template <class M>
double curve_cost(const ChannelTarget& target, const ChannelParameters& params) {
    double cost = 0;
    for (std::size_t i = 0; i < target.mu.size(); ++i) {
        const double r = target.scale[i] * (M::evaluate(params.data(), target.mu[i]) - target.value[i]);
        cost += 0.5 * r * r;
    }
    return cost;
}

// The plain fit of a model with two non-linear parameters left by its Projection: from each start, bounded
// Levenberg–Marquardt on the projected residuals; the cost compared and kept is that of the full parameters
// returned (ties keep the first). Starts with the same non-linear parameters take the same path: skipped; a start
// whose path comes within kSameMinimum of an earlier start's minimum is ending there: abandoned. A start
// whose cost at its first accepted step from iteration StartPruning::kIteration on is still above kFactor times the best final cost so far is
// abandoned (StartPruning's rule).
template <class M>
ChannelFit fit_projected_pair(const ChannelTarget& target, std::span<const NamedStart> starts,
                              typename M::Projection& projection) {
    constexpr auto kNonlinear = M::Projection::kNonlinearParameters;
    const std::array<double, 2> lower{M::kParameters[kNonlinear[0]].lower, M::kParameters[kNonlinear[1]].lower};
    const std::array<double, 2> upper{M::kParameters[kNonlinear[0]].upper, M::kParameters[kNonlinear[1]].upper};
    ChannelFit best;
    best.solver.final_cost = std::numeric_limits<double>::infinity();
    constexpr double kSameMinimum = 1e-6;
    std::vector<std::array<double, 2>> tried, minima;  // the starts' non-linear parameters; the minima found
    for (std::size_t s = 0; s < starts.size(); ++s) {
        const ChannelParameters x = clamp_to_bounds<M>(starts[s].params);
        const std::array<double, 2> z0{x[kNonlinear[0]], x[kNonlinear[1]]};
        if (std::find(tried.begin(), tried.end(), z0) != tried.end()) continue;
        tried.push_back(z0);
        const double best_so_far = best.solver.final_cost;
        const auto solve = bounded_levenberg_marquardt<2>(
            [&projection](const double* z, double* r, double* J) { return projection(z, r, J); },
            projection.residuals(), z0, lower, upper,
            [best_so_far, &minima, &lower, &upper](int iteration, double cost, const std::array<double, 2>& z) {
                if (iteration >= StartPruning::kIteration && std::isfinite(best_so_far) &&
                    cost > StartPruning::kFactor * best_so_far)
                    return false;
                // Within kSameMinimum of an earlier start's minimum (relative to the bounds' widths): the same
                // valley and minimum, and ties keep the first.
                for (const auto& m : minima)
                    if (std::abs(z[0] - m[0]) <= kSameMinimum * (upper[0] - lower[0]) &&
                        std::abs(z[1] - m[1]) <= kSameMinimum * (upper[1] - lower[1]))
                        return false;
                return true;
            });
        if (solve.abandoned || !std::isfinite(solve.cost)) continue;
        minima.push_back(solve.x);
        const ChannelParameters full = clamp_to_bounds<M>(projection.parameters(solve.x.data(), x));
        const double final_cost = curve_cost<M>(target, full);
        if (!std::isfinite(final_cost) || !(final_cost < best.solver.final_cost)) continue;
        if constexpr (CheckedCurve<M>)
            if (const std::string why = M::inadmissible(full.data()); !why.empty()) {
                if (best.discarded++ == 0) best.discarded_why = why;
                continue;
            }
        best.params = full;
        best.solver.method = kProjectedLmSolve;
        best.solver.start = starts[s].name;
        best.solver.iterations = solve.iterations;
        best.solver.termination =
            ceres::TerminationTypeToString(solve.converged ? ceres::CONVERGENCE : ceres::NO_CONVERGENCE);
        best.solver.initial_cost = solve.initial_cost;
        best.solver.final_cost = final_cost;
    }
    best.solver.starts = static_cast<int>(starts.size());
    return best;
}

// Fits from every start and keeps the lowest final cost (the first one on ties, so the result does not depend
// on anything but the starts' order).
template <class M>
ChannelFit fit_channel(const ChannelTarget& target, std::span<const NamedStart> starts,
                       const ChannelConstraints& constraints) {
    constexpr int kCount = static_cast<int>(M::kParameters.size());
    ceres::Solver::Options options;
    options.minimizer_type = ceres::TRUST_REGION;
    options.trust_region_strategy_type = ceres::LEVENBERG_MARQUARDT;
    options.linear_solver_type = ceres::DENSE_QR;
    options.max_num_iterations = 400;
    options.function_tolerance = 1e-15;
    options.gradient_tolerance = 1e-16;
    options.parameter_tolerance = 1e-14;
    options.num_threads = 1;
    options.logging_type = ceres::SILENT;

    const ConstraintSet active = constraint_set<M>(constraints);
    const int held = active.held_parameter();  // held by the solver, computed inside the residual
    // One solve from x with the parameters in `fixed` held at their values (besides the held one); x is updated.
    // Returns the cost of the parameters returned (NaN when not finite, or where the start cannot hold a constraint).
    const auto solve = [&](ChannelParameters& x, std::vector<int> fixed, ceres::Solver::Summary& summary,
                           StartPruning* pruning = nullptr) {
        ceres::Problem problem;
        active.add_residuals(problem, x.data());
        if (ceres::CostFunction* constrained = active.curve_residual(target)) {
            problem.AddResidualBlock(constrained, nullptr, x.data());
        } else {
            if constexpr (AnalyticGradient<M>)
                problem.AddResidualBlock(new AnalyticCurveResidual<M>(&target), nullptr, x.data());
            else
                problem.AddResidualBlock(new ceres::AutoDiffCostFunction<CurveResidual<M>, ceres::DYNAMIC, kCount>(
                                             new CurveResidual<M>{&target}, static_cast<int>(target.mu.size())),
                                         nullptr, x.data());
        }
        if (held >= 0) fixed.push_back(held);
        std::sort(fixed.begin(), fixed.end());
        fixed.erase(std::unique(fixed.begin(), fixed.end()), fixed.end());
        for (int i = 0; i < kCount; ++i) {
            if (std::find(fixed.begin(), fixed.end(), i) != fixed.end()) continue;
            problem.SetParameterLowerBound(x.data(), i, active.lower(i));
            problem.SetParameterUpperBound(x.data(), i, active.upper(i));
        }
        if (static_cast<int>(fixed.size()) == kCount)
            problem.SetParameterBlockConstant(x.data());
        else if (!fixed.empty())
            problem.SetManifold(x.data(), new ceres::SubsetManifold(kCount, fixed));
        if (pruning) {
            ceres::Solver::Options pruned_options = options;
            pruned_options.callbacks.push_back(pruning);
            ceres::Solve(pruned_options, &problem, &summary);
            if (pruning->pruned()) return std::numeric_limits<double>::quiet_NaN();
        } else {
            ceres::Solve(options, &problem, &summary);
        }
        if (!active.after_solve(problem, options, x, summary)) return std::numeric_limits<double>::quiet_NaN();
        // With an active bound the summary's final cost can differ (1e-4 relative) from the cost of the parameters
        // returned: evaluate them, so that starts are compared and reported on what is kept.
        double cost = std::numeric_limits<double>::quiet_NaN();
        problem.Evaluate(ceres::Problem::EvaluateOptions(), &cost, nullptr, nullptr, nullptr);
        return cost;
    };

    ChannelFit best;
    best.solver.final_cost = std::numeric_limits<double>::infinity();
    if constexpr (ProjectedFit<M>) {
        // Plain fits: each start's non-linear parameter minimised with the linear ones projected out (its linear
        // parameters are not used); the cost compared and kept is that of the full parameters returned. Starts with
        // the same non-linear parameter take the same path, and a start whose bracket holds the minimum of an earlier
        // one ends there: both skipped, ties keep the first (docs/decisions.md).
        if (active.keeps_projection()) {
            constexpr auto kNonlinear = M::Projection::kNonlinearParameters;
            static_assert(kNonlinear.size() <= 2, "variable projection leaves at most two non-linear parameters");
            typename M::Projection projection(target);
            if constexpr (kNonlinear.size() == 2) {
                return fit_projected_pair<M>(target, starts, projection);
            } else {
                std::vector<double> tried, minima;  // the starts' non-linear parameter; the minima found from them
                for (std::size_t s = 0; s < starts.size(); ++s) {
                    const ChannelParameters x = clamp_to_bounds<M>(starts[s].params);
                    std::array<double, kNonlinear.size()> z;
                    // Nothing non-linear: the projection is the solution (no iteration; the start's n is what differs).
                    int iterations = 0;
                    bool converged = true;
                    double initial_cost = 0;
                    if constexpr (kNonlinear.size() == 1) {
                        z[0] = x[kNonlinear[0]];
                        if (std::find(tried.begin(), tried.end(), z[0]) != tried.end()) continue;
                        tried.push_back(z[0]);
                        const Parameter& bounds = M::kParameters[kNonlinear[0]];
                        const LineMinimum m = line_minimum(
                            [&projection](double alpha) {
                                const auto p = projection.at(alpha);
                                return LinePoint{alpha, p.cost, p.slope};
                            },
                            z[0], bounds.lower, bounds.upper, minima);
                        if (m.same_as >= 0)
                            continue;  // the valley of an earlier start: its minimum, and ties keep the first
                        z[0] = m.minimum.x;
                        minima.push_back(z[0]);
                        iterations = m.evaluations;
                        converged = m.converged;
                        initial_cost = m.start.value;
                    }
                    const ChannelParameters full = clamp_to_bounds<M>(projection.parameters(z.data(), x));
                    const double final_cost = curve_cost<M>(target, full);
                    if (!std::isfinite(final_cost) || !(final_cost < best.solver.final_cost)) continue;
                    if constexpr (CheckedCurve<M>)
                        if (const std::string why = M::inadmissible(full.data()); !why.empty()) {
                            if (best.discarded++ == 0) best.discarded_why = why;
                            continue;  // e.g. a pole in [0, 1]: never kept
                        }
                    best.params = full;
                    best.solver.method = kNonlinear.size() > 0 ? kProjectedLineSolve : kLinearSolve;
                    best.solver.start = starts[s].name;
                    best.solver.iterations = iterations;
                    best.solver.termination =
                        ceres::TerminationTypeToString(converged ? ceres::CONVERGENCE : ceres::NO_CONVERGENCE);
                    best.solver.initial_cost = kNonlinear.size() > 0 ? initial_cost : final_cost;
                    best.solver.final_cost = final_cost;
                }
                best.solver.starts = static_cast<int>(starts.size());
                return best;
            }
        }
    }
    // A start equal to an earlier one (after clamping) takes the same path to the same cost, and ties keep the
    // first: it is skipped (rational's linearised starts and the closed forms repeat each other).
    std::vector<ChannelParameters> tried;
    const bool prune = active.keeps_start_pruning();
    for (std::size_t s = 0; s < starts.size(); ++s) {
        ChannelParameters x = clamp_to_bounds<M>(starts[s].params);
        active.prepare_start(x);
        const auto same_bits = [&x](const ChannelParameters& y) {
            return std::equal(x.begin(), x.end(), y.begin(), y.end(), [](double a, double b) {
                return std::bit_cast<std::uint64_t>(a) == std::bit_cast<std::uint64_t>(b);
            });
        };
        if (std::any_of(tried.begin(), tried.end(), same_bits)) continue;
        tried.push_back(x);
        ceres::Solver::Summary summary;
        StartPruning pruning(best.solver.final_cost);
        double final_cost = solve(x, {}, summary, prune && std::isfinite(best.solver.final_cost) ? &pruning : nullptr);
        if (!std::isfinite(final_cost)) continue;
        // Where LM ends on a bound, the projected steps crawl along it and stop short (Gulbrandsen on Rb, Cs: g = 1,
        // r off by 0.002-0.009, 2 % above the optimum): solve again with those parameters held on the bound and
        // keep that when it is better.
        int iterations = static_cast<int>(summary.iterations.size()) - 1;
        std::vector<int> on_bound;
        ChannelParameters y = x;
        for (int i = 0; i < kCount; ++i) {
            if (i == held) continue;
            const double lo = active.lower(i), hi = active.upper(i), tol = 1e-9 * (hi - lo);
            if (y[i] <= lo + tol)
                y[i] = lo, on_bound.push_back(i);
            else if (y[i] >= hi - tol)
                y[i] = hi, on_bound.push_back(i);
        }
        if (!on_bound.empty() && static_cast<int>(on_bound.size()) < kCount) {
            ceres::Solver::Summary polished;
            const double polished_cost = solve(y, on_bound, polished);
            if (std::isfinite(polished_cost) && polished_cost < final_cost * (1 - 1e-9)) {
                x = y, final_cost = polished_cost;
                iterations += static_cast<int>(polished.iterations.size()) - 1;
                summary.termination_type = polished.termination_type;
            }
        }
        active.finish(x);
        // Parameters that are no curve (rational: a root of the denominator in [0, 1], a pole) are discarded: the
        // best start without one is kept (docs/fitting.md).
        if constexpr (CheckedCurve<M>)
            if (const std::string why = M::inadmissible(x.data()); !why.empty()) {
                if (best.discarded++ == 0) best.discarded_why = why;
                continue;
            }
        if (final_cost < best.solver.final_cost) {
            best.params = x;
            best.solver.method = kCeresSolve;
            best.solver.start = starts[s].name;
            best.solver.iterations = iterations;
            best.solver.termination = ceres::TerminationTypeToString(summary.termination_type);
            best.solver.initial_cost = summary.initial_cost;
            best.solver.final_cost = final_cost;
        }
    }
    best.solver.starts = static_cast<int>(starts.size());
    return best;
}

}  // namespace metalfit::detail
