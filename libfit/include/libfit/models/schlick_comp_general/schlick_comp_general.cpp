#include "libfit/models/schlick_comp_general/schlick_comp_general.hpp"

#include <algorithm>

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
    const auto candidates = detail::compensation_candidates(t, {1.5, 2.0, 2.5, 3.0, 3.5, 4.0, 5.0, 6.0, 7.0, 8.0, 10.0, 12.0, 16.0, 20.0, 24.0, 32.0, 48.0, 64.0}, alpha.lower, alpha.upper, 32,
                                                            F0.lower, F0.upper, a.lower, a.upper);
    // The best α of each power: the (p, α) surface has several valleys (copper green of Babar: p ≈ 6, α ≈ 16 beside
    // p ≈ 7.4, α ≈ 6.6), so one start per power rather than the few best overall.
    std::vector<ChannelParameters> starts;
    std::vector<double> seen;
    for (const auto& c : candidates) {
        if (std::find(seen.begin(), seen.end(), c.power) != seen.end()) continue;
        seen.push_back(c.power);
        starts.push_back({c.F0, c.power, c.a, c.alpha});
    }
    return starts;
}

}  // namespace metalfit::models
