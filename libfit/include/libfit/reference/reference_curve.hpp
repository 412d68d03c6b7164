// The reference curve R_c(μ) of a material: exact spectral Fresnel → XYZ → RGB, white balanced.
#pragma once

#include <complex>
#include <span>
#include <string>
#include <vector>

#include "libfit/color/color.hpp"
#include "libfit/color/color_space.hpp"
#include "libfit/color/colorimetry.hpp"
#include "libfit/io/material.hpp"
#include "libfit/optics/stack_reflectance.hpp"
#include "libfit/spectral/dense_spectrum.hpp"

namespace metalfit {

// μ of the F82 angle (θ ≈ 81.8°), where F82-tint models take their tint: μ̄ = 1/7.
inline constexpr double kMuF82 = 1.0 / 7.0;

struct SpectralOptions {
    Interpolation interpolation = Interpolation::linear;
    OutOfRange out_of_range = OutOfRange::error;
};

// R_c(μ) = RGB_c(XYZ(F(·, μ))) / RGB_c(perfect reflector) (docs/colour.md, "White balance"), so R_c(0) = 1 in every
// space. η(λ) is sampled once on the colorimetry's 1 nm grid and kept as the per-λ constants of the real Fresnel form
// (optics/fresnel_real.hpp); each μ costs one real Fresnel evaluation per wavelength and one OCIO conversion. The
// batch forms evaluate several μ per wavelength at once (vectorised across μ; each μ's sum over λ keeps the order of
// the 1 nm summation, so a batch gives exactly the values of single calls). A material with layers (a film, a coat:
// io/layer_stack.hpp) integrates the stack's reflectance instead (optics/stack_reflectance.hpp), one μ at a time.
class ReferenceCurve {
public:
    // Throws InputError naming the material's file (or its film's or coat's) when its data do not cover 360–830 nm
    // (and options.out_of_range is error).
    ReferenceCurve(const Material& material, const Colorimetry& colorimetry, ColorSpaceConverter converter,
                   SpectralOptions options = {});

    RGB operator()(double mu) const;                                // white balanced
    XYZ xyz(double mu) const;                                       // before the colour space
    std::vector<RGB> operator()(std::span<const double> mu) const;  // white balanced, one per μ
    std::vector<XYZ> xyz(std::span<const double> mu) const;
    // RGB of the perfect reflector before white balance (provenance: about (1.00016, 0.99998,
    // 0.99976) for D65 in Linear Rec.709).
    RGB raw_white() const { return raw_white_; }
    const ColorSpaceConverter& converter() const { return converter_; }
    // With --extrapolate (OutOfRange::clamp): which quantity was held constant over which nanometres of the
    // colorimetry's grid, one line each (held_constant_ranges); empty when the data cover the grid.
    const std::vector<std::string>& held_constant() const { return held_constant_; }

private:
    // η² of every wavelength of the colorimetry's grid (SquaredIndex, as arrays) and the XYZ weights, as arrays.
    std::vector<double> eta2_re_, eta2_re_minus_1_, eta2_im_, eta2_norm2_;
    std::vector<double> weight_x_, weight_y_, weight_z_;
    std::vector<StackOptics<double>> stack_;  // per λ of the grid when the material has layers; empty otherwise
    Colorimetry colorimetry_;
    ColorSpaceConverter converter_;
    RGB raw_white_;
    std::vector<std::string> held_constant_;
};

// "k held at its 400 nm value over 360–400 nm (--extrapolate; measured 400–900 nm)" for each end of n and k that
// does not reach `needed`, when `options` extrapolate; empty otherwise.
std::vector<std::string> held_constant_ranges(const Material& material, const WavelengthRange& needed,
                                              const SpectralOptions& options);

}  // namespace metalfit
