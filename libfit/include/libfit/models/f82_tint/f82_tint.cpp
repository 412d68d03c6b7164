#include "libfit/models/f82_tint/f82_tint.hpp"

#include <cmath>

#include "libfit/reference/reference_curve.hpp"
#include "models/closed_form_support.hpp"

namespace metalfit::models {

std::vector<ClosedForm> F82Tint::closed_forms(const ClosedFormInput& input) {
    const RGB F0 = input.reference(1.0);
    const RGB F82 = input.reference(kMuF82);
    ClosedForm form{"r1-r82", "F0 = R(1), tint = R(1/7) / Schlick(F0, 1/7) (OpenPBR, Adobe)", {}};
    for (int c = 0; c < 3; ++c) {
        const double f0 = F0[c];
        const double schlick = Schlick::evaluate(&f0, kMuF82);
        if (std::abs(schlick) < 1e-12)
            form.channel[c].undefined = "Schlick(F0, 1/7) = 0";
        else
            form.channel[c].params = ChannelParameters{F0[c], F82[c] / schlick};
    }
    return {form};
}

}  // namespace metalfit::models
