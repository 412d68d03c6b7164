#include "libfit/models/conductor_rgb/conductor_rgb.hpp"

#include "models/closed_form_support.hpp"

namespace metalfit::models {

std::vector<ClosedForm> ConductorRgb::closed_forms(const ClosedFormInput& input) {
    const auto nk = [](std::complex<double> eta) { return ChannelParameters{eta.real(), eta.imag()}; };
    return {detail::closed_form_from_wavelengths(input, detail::kRgbWavelengths, "n, k of the data at 650, 550, 450 nm",
                                                 nk),
            detail::closed_form_from_wavelengths(input, detail::kThesisWavelengths,
                                                 "n, k of the data at 700, 550, 435 nm (the thesis)", nk)};
}

}  // namespace metalfit::models
