#include "libfit/models/schlick_comp/schlick_comp.hpp"

#include "libfit/models/compensation_projection.hpp"

namespace metalfit::models {

std::vector<ClosedForm> SchlickComp::closed_forms(const ClosedFormInput& input) {
    const RGB F0 = input.reference(1.0);
    ClosedForm form{"r1", "F0 = R(1), a = 0 (Schlick)", {}};
    for (int c = 0; c < 3; ++c) form.channel[c].params = ChannelParameters{F0[c], 0.0, 6.0};
    return {form};
}

std::vector<ChannelParameters> SchlickComp::target_starts(const ChannelTarget& t) {
    constexpr std::size_t kKept = 3;
    const auto& F0 = kParameters[0];
    const auto& a = kParameters[1];
    const auto& alpha = kParameters[2];
    const auto candidates =
        detail::compensation_candidates(t, {5.0}, alpha.lower, alpha.upper, 48, F0.lower, F0.upper, a.lower, a.upper);
    std::vector<ChannelParameters> starts;
    for (std::size_t i = 0; i < std::min(kKept, candidates.size()); ++i)
        starts.push_back({candidates[i].F0, candidates[i].a, candidates[i].alpha});
    return starts;
}

}  // namespace metalfit::models
