#include "libfit/models/lazanyi/lazanyi.hpp"

#include <cmath>

#include "models/closed_form_support.hpp"

namespace metalfit::models {

namespace {

// n, k with ((n − 1)² + k²)/((n + 1)² + k²) = F0, keeping the measured n when some k ≥ 0 allows it; otherwise
// k = 0 and the dielectric n nearest the measured one.
ClosedFormChannel nk_from_F0(double F0, double measured_n) {
    if (!(F0 < 1.0)) return {{}, "R(1) = " + detail::format_number(F0) + " >= 1, beyond any F0(n, k) < 1"};
    if (!(F0 >= 0.0)) return {{}, "R(1) = " + detail::format_number(F0) + " < 0"};
    const double n = measured_n;
    const double k2 = (F0 * (n + 1.0) * (n + 1.0) - (n - 1.0) * (n - 1.0)) / (1.0 - F0);
    if (k2 >= 0.0) return {ChannelParameters{n, std::sqrt(k2)}, {}};
    const double s = std::sqrt(F0);
    const double above = (1.0 + s) / (1.0 - s), below = (1.0 - s) / (1.0 + s);
    return {ChannelParameters{std::abs(above - n) < std::abs(below - n) ? above : below, 0.0}, {}};
}

}  // namespace

ChannelParameters Lazanyi::nk_with_F0(double F0) {
    if (!(F0 < 1.0 - 1e-12)) return {kParameters[0].lower, kParameters[1].upper};
    if (!(F0 > 0.0)) return {1.0, 0.0};
    return {1.0, 2.0 * std::sqrt(F0 / (1.0 - F0))};
}

ChannelParameters Lazanyi::nk_near(double F0, double n) {
    if (!(F0 < 1.0 - 1e-12) || !(F0 > 0.0)) return nk_with_F0(F0);
    const double k2 = (F0 * (n + 1.0) * (n + 1.0) - (n - 1.0) * (n - 1.0)) / (1.0 - F0);
    if (k2 >= 0.0) return {n, std::sqrt(k2)};
    const double s = std::sqrt(F0);
    const double above = (1.0 + s) / (1.0 - s), below = (1.0 - s) / (1.0 + s);
    return {std::abs(above - n) < std::abs(below - n) ? above : below, 0.0};
}

std::vector<ChannelParameters> Lazanyi::target_starts(const ChannelTarget& t) {
    return {nk_with_F0(least_squares_F0(t))};
}

double Lazanyi::least_squares_F0(const ChannelTarget& t) {
    // residual_i = s_i (F0 (1 − w_i) − (R_i − w_i)), w = (1 − μ)^5.
    double xx = 0.0, xy = 0.0;
    for (std::size_t i = 0; i < t.mu.size(); ++i) {
        const double w = model_math::schlick_weight(t.mu[i]);
        const double x = t.scale[i] * (1.0 - w), y = t.scale[i] * (t.value[i] - w);
        xx += x * x;
        xy += x * y;
    }
    return xy / xx;
}

std::vector<ClosedForm> Lazanyi::closed_forms(const ClosedFormInput& input) {
    ClosedForm sampled = detail::closed_form_from_wavelengths(input, detail::kThesisWavelengths,
                                                              "n, k of the data at 700, 550, 435 nm (the thesis)",
                                                              [](std::complex<double> eta) {
                                                                  return ChannelParameters{eta.real(), eta.imag()};
                                                              });

    ClosedForm r1{"r1", "F0 = R(1); n from 700, 550, 435 nm, k solved", {}};
    const RGB F0 = input.reference(1.0);
    for (int c = 0; c < 3; ++c) {
        const detail::SampledEta s = detail::sample_eta(input, detail::kThesisWavelengths[c]);
        r1.channel[c] = s.error.empty() ? nk_from_F0(F0[c], s.eta.real()) : ClosedFormChannel{{}, s.error};
    }
    return {sampled, r1};
}

}  // namespace metalfit::models
