// The residuals of one channel's least squares (internal): what the plain fit and the constrained ones (--pin F0,
// --f0-tolerance) evaluate, each on its own parameter vector.
#pragma once

#include <cstddef>

#include "libfit/reference/channel_target.hpp"

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

}  // namespace metalfit::detail
