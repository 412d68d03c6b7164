#include "libfit/models/schlick_comp_general/schlick_comp_general.hpp"

#include <algorithm>
#include <cmath>
#include <utility>

#include "models/compensation_projection.hpp"

namespace metalfit::models {

std::vector<ClosedForm> SchlickCompGeneral::closed_forms(const ClosedFormInput& input) {
    const RGB F0 = input.reference(1.0);
    ClosedForm form{"r1", "F0 = R(1), p = 5, a = 0 (Schlick)", {}};
    for (int c = 0; c < 3; ++c) form.channel[c].params = ChannelParameters{F0[c], 5.0, 0.0, 6.0};
    return {form};
}

std::vector<ChannelParameters> SchlickCompGeneral::target_starts(const ChannelTarget& t) {
    const auto& F0 = kParameters[0];
    const auto& a = kParameters[2];
    const auto& alpha = kParameters[3];
    const std::vector<double> powers{1.5, 2.0,  2.5,  3.0,  3.5,  4.0,  5.0,  6.0,  7.0,
                                     8.0, 10.0, 12.0, 16.0, 20.0, 24.0, 32.0, 48.0, 64.0};
    const auto candidates =
        detail::compensation_candidates(t, powers, alpha.lower, alpha.upper, 32, F0.lower, F0.upper, a.lower, a.upper);
    // The best α of each power: the (p, α) surface has several valleys (copper green of Babar: p ≈ 6, α ≈ 16 beside
    // p ≈ 7.4, α ≈ 6.6), so one start per power rather than the few best overall.
    std::vector<ChannelParameters> starts;
    std::vector<double> seen;
    for (const auto& c : candidates) {
        if (std::find(seen.begin(), seen.end(), c.power) != seen.end()) continue;
        seen.push_back(c.power);
        starts.push_back({c.F0, c.power, c.a, c.alpha});
    }
    // Where the data need almost no compensation the α of a power's best candidate is arbitrary and can lead LM into
    // another valley (vanadium nitride red of Pflüger: 0.0027 at p = 16.9, a = −3.5 instead of 0.0022 at p = 9.7,
    // a = 0.02): the best powers of the uncompensated curve F0 + (1 − F0) mᵖ (a = 0, α = 1) start as well.
    std::vector<std::pair<double, ChannelParameters>> uncompensated;  // (½ Σ residual², start)
    for (double power : powers) {
        double Ay = 0.0, AA = 0.0;
        for (std::size_t i = 0; i < t.mu.size(); ++i) {
            const double w = std::pow(1.0 - t.mu[i], power), A = t.scale[i] * (1.0 - w),
                         y = t.scale[i] * (t.value[i] - w);
            Ay += A * y, AA += A * A;
        }
        if (!(AA > 0.0)) continue;
        const double f0 = std::clamp(Ay / AA, F0.lower, F0.upper);
        double cost = 0.0;
        for (std::size_t i = 0; i < t.mu.size(); ++i) {
            const double w = std::pow(1.0 - t.mu[i], power), r = t.scale[i] * ((1.0 - w) * f0 - (t.value[i] - w));
            cost += 0.5 * r * r;
        }
        uncompensated.push_back({cost, ChannelParameters{f0, power, 0.0, 1.0}});
    }
    std::stable_sort(uncompensated.begin(), uncompensated.end(),
                     [](const auto& x, const auto& y) { return x.first < y.first; });
    for (std::size_t i = 0; i < uncompensated.size() && i < 3; ++i) starts.push_back(uncompensated[i].second);
    return starts;
}

}  // namespace metalfit::models
