#include "libfit/models/schlick/schlick.hpp"

namespace metalfit::models {

std::vector<ClosedForm> Schlick::closed_forms(const ClosedFormInput& input) {
    const RGB F0 = input.reference(1.0);
    ClosedForm form{"r1", "F0 = R(1)", {}};
    for (int c = 0; c < 3; ++c) form.channel[c].params = ChannelParameters{F0[c]};
    return {form};
}

}  // namespace metalfit::models
