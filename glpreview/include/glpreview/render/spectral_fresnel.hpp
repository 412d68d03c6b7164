// The exact spectral Fresnel F(λ, μ) of a sphere's material on the colorimetry's 1 nm grid (360–830 nm): the same
// per-λ constants of the real Fresnel form as libfit's ReferenceCurve (optics/fresnel_real.hpp), or the layer
// stack's reflectance when the material has a film or a coat. The spectral reference multiplies these along a path.
#pragma once

#include <span>
#include <vector>

#include "libfit/color/colorimetry.hpp"
#include "libfit/io/material.hpp"
#include "libfit/optics/stack_reflectance.hpp"
#include "libfit/reference/reference_curve.hpp"

namespace metalfit::glpreview {

class SpectralFresnel {
public:
    // Throws InputError when the material's data do not cover the grid (as ReferenceCurve does).
    SpectralFresnel(const Material& material, const Colorimetry& colorimetry, SpectralOptions options = {});

    std::size_t size() const { return eta2_re_.empty() ? stack_.size() : eta2_re_.size(); }  // wavelengths
    // spectrum[i] *= F(λ_i, μ) for every wavelength of the grid (μ clamped to [0, 1]); spectrum.size() == size().
    void multiply(double mu, std::span<double> spectrum) const;

private:
    std::vector<double> eta2_re_, eta2_re_minus_1_, eta2_im_, eta2_norm2_;
    std::vector<StackOptics<double>> stack_;  // per λ when the material has layers; the η² columns are then empty
};

}  // namespace metalfit::glpreview
