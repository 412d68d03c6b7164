#include "libfit/models/schlick_comp_linear/schlick_comp_linear.hpp"

#include <algorithm>
#include <cmath>

#include "models/linear_least_squares.hpp"

namespace metalfit::models {

std::vector<ClosedForm> SchlickCompLinear::closed_forms(const ClosedFormInput& input) {
    const RGB F0 = input.reference(1.0);
    ClosedForm form{"r1", "F0 = R(1), b1 = b2 = 0 (Schlick)", {}};
    for (int c = 0; c < 3; ++c) form.channel[c].params = ChannelParameters{F0[c], 0.0, 0.0};
    return {form};
}

std::vector<ChannelParameters> SchlickCompLinear::target_starts(const ChannelTarget& t) {
    // residual_i = s_i (F0 (1 − m⁵) − b1 μ m⁴ − b2 μ m⁹ − (R_i − m⁵)).
    std::vector<std::vector<double>> A(3);
    std::vector<double> y;
    for (std::size_t i = 0; i < t.mu.size(); ++i) {
        const double mu = t.mu[i], m = 1.0 - mu, m4 = m * m * m * m, s = t.scale[i];
        A[0].push_back(s * (1.0 - m4 * m));
        A[1].push_back(-s * mu * m4);
        A[2].push_back(-s * mu * m4 * m4 * m);
        y.push_back(s * (t.value[i] - m4 * m));
    }
    const auto x = detail::linear_least_squares(std::move(A), std::move(y));
    if (!x) return {};
    ChannelParameters p = *x;
    for (std::size_t i = 0; i < p.size(); ++i) p[i] = std::clamp(p[i], kParameters[i].lower, kParameters[i].upper);
    return {p};
}

}  // namespace metalfit::models
