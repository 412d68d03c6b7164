// Ceres least squares of one channel of one model (internal: the model adapters in model.cpp instantiate it for every registered model).
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
#include <vector>

namespace metalfit::detail {

// Residuals of one channel at the quadrature nodes: scale_i (M(p, μ_i) − R_i). A tiny templated functor
// evaluated with Jets, as in the Ceres examples.
template <class M>
struct CurveResidual {
    const ChannelTarget* target;

    template <class T>
    bool operator()(const T* params, T* residuals) const {
        const auto n = target->mu.size();
        for (std::size_t i = 0; i < n; ++i)
            residuals[i] = T(target->scale[i]) * (M::evaluate(params, T(target->mu[i])) - T(target->value[i]));
        return true;
    }
};

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

// The same with F(1) pinned (--pin F0): the pinned parameter is recomputed from the others before each evaluation
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
        const auto n = target->mu.size();
        for (std::size_t i = 0; i < n; ++i)
            residuals[i] = T(target->scale[i]) * (M::evaluate(q.data(), T(target->mu[i])) - T(target->value[i]));
        return true;
    }
};

// --f0-tolerance: F(1) is an unknown of the solve held in the pinned parameter's slot of the parameter block, bounded
// to the tolerance's interval; the pinned parameter is recomputed from the others and that F(1) before each evaluation
// (as PinnedCurveResidual), so the solve is the bounded least squares of the reparameterised curve: a true optimum
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
        const auto n = target->mu.size();
        for (std::size_t i = 0; i < n; ++i)
            residuals[i] = T(target->scale[i]) * (M::evaluate(q.data(), T(target->mu[i])) - T(target->value[i]));
        return true;
    }
};

// --gamut-fit: weight · (how far M(p, μ_j) is outside [0, upper]) on the uniform grid of μ the constraint is checked
// on, zero inside. `limits` is
// the solver's own: its weight grows and its upper end tightens between solves of the same problem.
struct GamutLimits {
    static constexpr int kGrid = 4097;  // the grid --gamut-fit is checked on (gamut_excess)
    double weight = 0;                  // 0 and stride kGrid: the first solve is the unconstrained one
    double upper = 1;
    int stride = kGrid;  // every stride-th point: 257 while the penalty stiffens, then every point
};

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

template <class M>
ChannelParameters clamp_to_bounds(ChannelParameters p) {
    for (std::size_t i = 0; i < M::kParameters.size(); ++i)
        p[i] = std::clamp(p[i], M::kParameters[i].lower, M::kParameters[i].upper);
    return p;
}

// Start pruning of the plain fits (no --pin F0, no --gamut-fit): a start whose cost after kIteration iterations of
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

    // One solve from x with the parameters in `fixed` held at their values (besides the pinned one); x is updated.
    // Returns the cost of the parameters returned (NaN when not finite).
    int pinned = -1;
    if constexpr (PinnableF0<M>)
        if (constraints.pinned_f0) pinned = static_cast<int>(M::kPinnedParameter);
    if (constraints.pinned_f0 && pinned < 0) throw std::logic_error(std::string(M::kId) + " cannot pin F0");
    // --f0-tolerance: the pinned parameter's slot holds F(1) during the solves, bounded to f0_range.
    int ranged = -1;
    if constexpr (PinnableF0<M>)
        if (constraints.f0_range) ranged = static_cast<int>(M::kPinnedParameter);
    if (constraints.f0_range && ranged < 0) throw std::logic_error(std::string(M::kId) + " cannot bound F0");
    const auto lower_bound = [&](int i) { return i == ranged ? (*constraints.f0_range)[0] : M::kParameters[i].lower; };
    const auto upper_bound = [&](int i) { return i == ranged ? (*constraints.f0_range)[1] : M::kParameters[i].upper; };
    const auto solve = [&](ChannelParameters& x, std::vector<int> fixed, ceres::Solver::Summary& summary,
                           StartPruning* pruning = nullptr) {
        ceres::Problem problem;
        GamutLimits limits;
        if (constraints.unit_range)
            problem.AddResidualBlock(new ceres::AutoDiffCostFunction<GamutPenalty<M>, GamutLimits::kGrid, kCount>(
                                         new GamutPenalty<M>{&limits}),
                                     nullptr, x.data());
        const int residuals = static_cast<int>(target.mu.size());
        if constexpr (PinnableF0<M>) {
            if (pinned >= 0)
                problem.AddResidualBlock(
                    new ceres::AutoDiffCostFunction<PinnedCurveResidual<M>, ceres::DYNAMIC, kCount>(
                        new PinnedCurveResidual<M>{&target, *constraints.pinned_f0}, residuals),
                    nullptr, x.data());
        }
        if constexpr (PinnableF0<M>) {
            if (ranged >= 0)
                problem.AddResidualBlock(new ceres::AutoDiffCostFunction<F0RangeResidual<M>, ceres::DYNAMIC, kCount>(
                                             new F0RangeResidual<M>{&target}, residuals),
                                         nullptr, x.data());
        }
        if (pinned < 0 && ranged < 0) {
            if constexpr (AnalyticGradient<M>)
                problem.AddResidualBlock(new AnalyticCurveResidual<M>(&target), nullptr, x.data());
            else
                problem.AddResidualBlock(new ceres::AutoDiffCostFunction<CurveResidual<M>, ceres::DYNAMIC, kCount>(
                                             new CurveResidual<M>{&target}, residuals),
                                         nullptr, x.data());
        }
        if (pinned >= 0) fixed.push_back(pinned);
        std::sort(fixed.begin(), fixed.end());
        fixed.erase(std::unique(fixed.begin(), fixed.end()), fixed.end());
        for (int i = 0; i < kCount; ++i) {
            if (std::find(fixed.begin(), fixed.end(), i) != fixed.end()) continue;
            problem.SetParameterLowerBound(x.data(), i, lower_bound(i));
            problem.SetParameterUpperBound(x.data(), i, upper_bound(i));
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
        if (constraints.unit_range) {
            // Where the unconstrained solution leaves [0, 1]: continuation, a stiffer penalty from the last solution,
            // then the upper end lowered by what is still outside until the 4097-point grid holds the curve. The cost returned is the penalty-free curve cost.
            const double initial_cost = summary.initial_cost;
            if (gamut_excess<M>(x) > kGamutTolerance) {  // else the unconstrained optimum of this start holds already
                limits.stride = 16;
                for (const double weight : {1e2, 1e4, 1e6}) {
                    limits.weight = weight;
                    ceres::Solve(options, &problem, &summary);
                }
            }
            limits.stride = 1;
            for (int round = 0; round < 8; ++round) {
                const double excess = gamut_excess<M>(x);
                if (!(excess > kGamutTolerance)) break;
                limits.upper -= 2 * excess + 1e-12;
                ceres::Solve(options, &problem, &summary);
            }
            summary.initial_cost = initial_cost;
            if (!(gamut_excess<M>(x) <= kGamutTolerance))
                return std::numeric_limits<double>::quiet_NaN();  // this start cannot hold it
            limits.weight = 0;
        }
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
        if (!constraints.unit_range && !constraints.pinned_f0 && !constraints.f0_range) {
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
    const bool prune = !constraints.unit_range && !constraints.pinned_f0 && !constraints.f0_range;
    for (std::size_t s = 0; s < starts.size(); ++s) {
        ChannelParameters x = clamp_to_bounds<M>(starts[s].params);
        if constexpr (PinnableF0<M>)
            if (ranged >= 0)
                x[ranged] = std::clamp(M::evaluate(x.data(), 1.0), lower_bound(ranged), upper_bound(ranged));
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
            if (i == pinned) continue;
            const double lo = lower_bound(i), hi = upper_bound(i), tol = 1e-9 * (hi - lo);
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
        if constexpr (PinnableF0<M>) {
            if (pinned >= 0)
                x[M::kPinnedParameter] = M::pinned_value(x.data(), *constraints.pinned_f0);
            else if (ranged >= 0)
                x[M::kPinnedParameter] = M::pinned_value(x.data(), x[M::kPinnedParameter]);
        }
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
