#include "libfit/models/gulbrandsen/gulbrandsen.hpp"

#include <cmath>

#include "libfit/optics/fresnel.hpp"
#include "models/closed_form_support.hpp"

namespace metalfit::models {

std::array<double, 2> Gulbrandsen::from_nk(std::complex<double> eta) {
    const double r = fresnel_normal_incidence(eta);
    const double sr = std::sqrt(r);
    const double n_min = (1.0 - r) / (1.0 + r);
    const double n_max = (1.0 + sr) / (1.0 - sr);
    const double g = n_max - n_min > 0.0 ? (n_max - eta.real()) / (n_max - n_min) : 0.0;
    return {r, g};
}

std::complex<double> Gulbrandsen::to_nk(double r, double g) { return {n_of(r, g), std::sqrt(k2_of(r, g))}; }

std::vector<ClosedForm> Gulbrandsen::closed_forms(const ClosedFormInput& input) {
    const auto rg = [](std::complex<double> eta) {
        const auto [r, g] = from_nk(eta);
        return ChannelParameters{r, g};
    };
    return {detail::closed_form_from_wavelengths(input, detail::kRgbWavelengths,
                                                 "r, g of the data's n, k at 650, 550, 450 nm", rg),
            detail::closed_form_from_wavelengths(input, detail::kThesisWavelengths,
                                                 "r, g of the data's n, k at 700, 550, 435 nm", rg)};
}

}  // namespace metalfit::models
