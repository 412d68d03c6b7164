#include "libfit/models/schlick_comp_general/schlick_comp_general.hpp"

#include "models/compensation_projection.hpp"

namespace metalfit::models {

std::vector<ClosedForm> SchlickCompGeneral::closed_forms(const ClosedFormInput& input) {
    const RGB F0 = input.reference(1.0);
    ClosedForm form{"r1", "F0 = R(1), p = 5, a = 0 (Schlick)", {}};
    for (int c = 0; c < 3; ++c) form.channel[c].params = ChannelParameters{F0[c], 5.0, 0.0, 6.0};
    return {form};
}

std::vector<ChannelParameters> SchlickCompGeneral::target_starts(const ChannelTarget& t) {
    constexpr std::size_t kKept = 4;
    const auto& F0 = kParameters[0];
    const auto& a = kParameters[2];
    const auto& alpha = kParameters[3];
    const auto candidates = detail::compensation_candidates(t, {3.0, 4.0, 5.0, 6.0, 8.0}, alpha.lower, alpha.upper, 32,
                                                            F0.lower, F0.upper, a.lower, a.upper);
    std::vector<ChannelParameters> starts;
    for (std::size_t i = 0; i < std::min(kKept, candidates.size()); ++i)
        starts.push_back({candidates[i].F0, candidates[i].power, candidates[i].a, candidates[i].alpha});
    return starts;
}

}  // namespace metalfit::models
