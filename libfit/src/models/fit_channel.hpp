// Ceres least squares of one channel of one model (internal: the model adapters in model.cpp instantiate it for every registered model).
#pragma once

#include <ceres/ceres.h>

#include <algorithm>
#include <cmath>
#include <limits>
#include <span>
#include <string>

#include "libfit/models/model.hpp"

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

template <class M>
ChannelParameters clamp_to_bounds(ChannelParameters p) {
    for (std::size_t i = 0; i < M::kParameters.size(); ++i)
        p[i] = std::clamp(p[i], M::kParameters[i].lower, M::kParameters[i].upper);
    return p;
}

// Fits from every start and keeps the lowest final cost (the first one on ties, so the result does not depend
// on anything but the starts' order).
template <class M>
ChannelFit fit_channel(const ChannelTarget& target, std::span<const NamedStart> starts) {
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

    ChannelFit best;
    best.solver.final_cost = std::numeric_limits<double>::infinity();
    for (std::size_t s = 0; s < starts.size(); ++s) {
        ChannelParameters x = clamp_to_bounds<M>(starts[s].params);
        ceres::Problem problem;
        auto* cost = new ceres::AutoDiffCostFunction<CurveResidual<M>, ceres::DYNAMIC, kCount>(
            new CurveResidual<M>{&target}, static_cast<int>(target.mu.size()));
        problem.AddResidualBlock(cost, nullptr, x.data());
        for (int i = 0; i < kCount; ++i) {
            problem.SetParameterLowerBound(x.data(), i, M::kParameters[i].lower);
            problem.SetParameterUpperBound(x.data(), i, M::kParameters[i].upper);
        }
        ceres::Solver::Summary summary;
        ceres::Solve(options, &problem, &summary);
        // With an active bound the summary's final cost can differ (1e-4 relative) from the cost of the parameters
        // returned: evaluate them, so that starts are compared and reported on what is kept.
        double final_cost = std::numeric_limits<double>::quiet_NaN();
        problem.Evaluate(ceres::Problem::EvaluateOptions(), &final_cost, nullptr, nullptr, nullptr);
        if (!std::isfinite(final_cost)) continue;
        if (final_cost < best.solver.final_cost) {
            best.params = x;
            best.solver.start = starts[s].name;
            best.solver.iterations = static_cast<int>(summary.iterations.size()) - 1;
            best.solver.termination = ceres::TerminationTypeToString(summary.termination_type);
            best.solver.initial_cost = summary.initial_cost;
            best.solver.final_cost = final_cost;
        }
    }
    best.solver.starts = static_cast<int>(starts.size());
    return best;
}

}  // namespace metalfit::detail
