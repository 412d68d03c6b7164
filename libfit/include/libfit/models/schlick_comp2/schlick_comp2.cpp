#include "libfit/models/schlick_comp2/schlick_comp2.hpp"

namespace metalfit::models {

std::vector<ClosedForm> SchlickComp2::closed_forms(const ClosedFormInput& input) {
    const RGB F0 = input.reference(1.0);
    ClosedForm form{"r1", "F0 = R(1), b1 = b2 = 0 (Schlick)", {}};
    for (int c = 0; c < 3; ++c) form.channel[c].params = ChannelParameters{F0[c], 0.0, 0.0};
    return {form};
}

}  // namespace metalfit::models
