// Helpers shared by the closed forms of the models (internal).
#pragma once

#include <array>
#include <complex>
#include <cstdio>
#include <exception>
#include <string>

#include "libfit/base/number_text.hpp"
#include "libfit/models/model.hpp"

namespace metalfit::detail {

// Wavelengths (nm) at which renderers sample n, k for R, G, B.
inline constexpr std::array<double, 3> kThesisWavelengths{700.0, 550.0, 435.0};  // Lazányi's thesis
inline constexpr std::array<double, 3> kRgbWavelengths{650.0, 550.0, 450.0};     // common renderer choice

inline std::string wavelength_form_id(const std::array<double, 3>& nm) {
    return "nk-" + fixed_text(nm[0], 0) + "-" + fixed_text(nm[1], 0) + "-" + fixed_text(nm[2], 0);
}

inline std::string format_number(double x) { return significant_text(x, 6); }

// η at λ, or the reason it is not available (outside the data; a target without a complex index, such as a
// measured reflectance: fit/fit_target.hpp).
struct SampledEta {
    std::complex<double> eta;
    std::string error;
};
inline constexpr const char* kNoComplexIndex = "undefined: the target has no complex index";
inline SampledEta sample_eta(const ClosedFormInput& input, double nm) {
    if (!input.eta) return {{}, kNoComplexIndex};
    try {
        return {input.eta(nm), {}};
    } catch (const std::exception& e) {
        return {{}, e.what()};
    }
}

// A closed form made by sampling η at one wavelength per channel and mapping it to parameters.
template <class MapEta>
ClosedForm closed_form_from_wavelengths(const ClosedFormInput& input, const std::array<double, 3>& nm,
                                        std::string description, MapEta map_eta) {
    ClosedForm form{wavelength_form_id(nm), std::move(description), {}};
    for (int c = 0; c < 3; ++c) {
        const SampledEta s = sample_eta(input, nm[c]);
        if (!s.error.empty())
            form.channel[c].undefined = s.error;
        else
            form.channel[c].params = map_eta(s.eta);
    }
    return form;
}

}  // namespace metalfit::detail
