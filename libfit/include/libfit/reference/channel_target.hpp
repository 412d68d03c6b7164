// One channel of a reference curve at the quadrature nodes, ready for least squares (what a model is fitted to).
#pragma once

#include <vector>

namespace metalfit {

// residual_i = scale_i (M(μ_i) − value_i) with scale_i = sqrt(W_i w(μ_i)) / (value_i for rel, 1 for abs),
// so that ½ Σ residual² = ½ (chosen rms)².
struct ChannelTarget {
    std::vector<double> mu;
    std::vector<double> value;
    std::vector<double> scale;
};

}  // namespace metalfit
