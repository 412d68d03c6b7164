// The spectral reference's light: the environment's RGB radiance lifted to a spectrum by a smooth linear method.
//
// Three smooth windows over 360–830 nm, a partition of unity made of two logistic sigmoids (centres 490 and 585 nm,
// scale 15 nm): g_red(λ) = s(λ − 585), g_green(λ) = s(λ − 490) − s(λ − 585), g_blue(λ) = 1 − s(λ − 490). Their
// white-balanced RGB under the scene's CMF, illuminant and working space (the reference curves' integration:
// R = RGB(Σ_λ S(λ) w(λ)) / RGB(perfect reflector)) are the columns of a 3×3 matrix P; the basis functions
// b_c = Σ_j (P⁻¹)_jc g_j then have RGB(b_c) = e_c exactly, so that L(λ) = Σ_c L_c b_c(λ) integrates back to L
// (to the float32 of the OCIO step). Because the constant 1 = Σ_j g_j lies in their span and integrates to
// (1, 1, 1), Σ_c b_c ≡ 1: grey light stays spectrally flat, and one bounce of grey light under the spectral
// reference is the RGB reference curve R_c(μ) times the grey. The method is linear (a sum of light is the sum of
// its spectra) and smooth; the b_c may dip below zero at some wavelengths (a saturated primary's spectrum is not a
// reflectance), which a linear method accepts where Jakob and Hanika's sigmoid uplift ("A Low-Dimensional Function
// Space for Efficient Spectral Upsampling", 2019) is non-linear and stays in [0, 1].
#pragma once

#include <array>
#include <span>
#include <vector>

#include "libfit/color/color.hpp"
#include "libfit/color/color_space.hpp"
#include "libfit/color/colorimetry.hpp"

namespace metalfit::glpreview {

class RgbUplift {
public:
    RgbUplift(const Colorimetry& colorimetry, ColorSpaceConverter converter);

    std::size_t size() const { return weights_.size(); }  // wavelengths of the 1 nm grid
    const std::vector<double>& basis(int c) const { return basis_[static_cast<std::size_t>(c)]; }
    // L(λ) = Σ_c L_c b_c(λ) on the grid.
    std::vector<double> spectrum(const RGB& radiance) const;
    // The white-balanced RGB of Σ_λ T(λ) L(λ) w(λ): light of RGB `radiance` after a path of spectral throughput T.
    RGB rgb(std::span<const double> throughput, const RGB& radiance) const;
    // The white-balanced RGB of a spectrum S on the grid: RGB(Σ_λ S(λ) w(λ)) / RGB(perfect reflector).
    RGB rgb_of(std::span<const double> spectrum) const;

private:
    std::vector<XYZ> weights_;                  // w(λ) of the colorimetry
    std::array<std::vector<double>, 3> basis_;  // b_c(λ)
    std::array<std::vector<XYZ>, 3> lifted_;    // b_c(λ) w(λ)
    ColorSpaceConverter converter_;
    RGB raw_white_;
};

}  // namespace metalfit::glpreview
