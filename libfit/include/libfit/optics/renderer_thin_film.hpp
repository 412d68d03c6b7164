// What renderers draw for a metal under a thin film: their RGB approximations of the film's Airy reflectance, next to
// which `fit/renderer_film_scores` puts the exact spectral curve (optics/stack_reflectance.hpp). docs/colour.md, "What
// renderers draw for a thin film".
//
// - materialx_thin_film: MaterialX 1.39.4's mx_fresnel_airy (libraries/pbrlib/genglsl/lib/mx_microfacet_specular.glsl,
//   the version of the MaterialX the export tests run), in double instead of GLSL's float: the conductor's n, k per
//   RGB channel, a real film index, the series to m = 2, each XYZ sensitivity paired with one RGB channel of the
//   metal, and CIE 1931 RGB (white E) as the output space. A thickness of 0 is MaterialX's bare conductor Fresnel
//   (its FresnelData has `airy = tf_thickness > 0`).
// - belcour_barla_thin_film: Laurent Belcour & Pascal Barla, "A Practical Extension to Microfacet Theory for the
//   Modeling of Varying Iridescence" (2017): the Airy series' Fourier terms integrated against Gaussian fits of the
//   CIE 1931 colour matching functions (the paper's "spectral antialiasing"), the DC term weighted by the
//   sensitivity at zero path difference, the series to m = 3, the film index ramped from 1 over the first 30 nm as
//   the authors' code does, CIE 1931 RGB out (or another matrix: the working space's); each RGB channel of the metal
//   is integrated on its own and keeps its own channel of the result (the paper's conductor is one index).
// - three_wavelength_airy: the exact Airy at one wavelength per channel (Adobe's and Cycles' scheme): the stack's
//   optics at 650, 550 and 450 nm, each channel that wavelength's exact reflectance.
#pragma once

#include <array>
#include <complex>

#include "libfit/optics/stack_reflectance.hpp"

namespace metalfit {

using ChannelIndices = std::array<std::complex<double>, 3>;  // n + ik of the metal per RGB channel
using ChannelReflectance = std::array<double, 3>;

// The wavelengths of three_wavelength_airy's channels (nm): red, green, blue.
inline constexpr std::array<double, 3> kThreeWavelengthsNm{650.0, 550.0, 450.0};

// MaterialX's mx_eval_sensitivity: the CIE 1931 x̄, ȳ, z̄ (white E, normalised to about 1 at zero path difference)
// integrated against cos(2π·opd·ν + shift) over the wavenumber ν, as Gaussian fits; opd in metres, one shift per
// component.
std::array<double, 3> thin_film_sensitivity(double opd_m, const std::array<double, 3>& shift);

// Belcour & Barla's and MaterialX's XYZ (white E) → CIE 1931 RGB matrix, rows.
using XyzToRgbMatrix = std::array<std::array<double, 3>, 3>;
inline constexpr XyzToRgbMatrix kXyzToCie1931Rgb{
    {{2.3706743, -0.9000405, -0.4706338}, {-0.5138850, 1.4253036, 0.0885814}, {0.0052982, -0.0146949, 1.0093968}}};

// μ = cos θ in air; film_ior real (MaterialX's tf_ior), thickness in nm.
ChannelReflectance materialx_thin_film(double mu, const ChannelIndices& metal, double film_ior, double thickness_nm);
// xyz_to_rgb: the paper's CIE 1931 RGB by default, or another XYZ (white E) → RGB matrix (rows).
ChannelReflectance belcour_barla_thin_film(double mu, const ChannelIndices& metal, double film_ior, double thickness_nm,
                                           const XyzToRgbMatrix& xyz_to_rgb);
ChannelReflectance belcour_barla_thin_film(double mu, const ChannelIndices& metal, double film_ior,
                                           double thickness_nm);
// optics[c]: the stack at kThreeWavelengthsNm[c].
ChannelReflectance three_wavelength_airy(double mu, const std::array<StackOptics<double>, 3>& optics);

}  // namespace metalfit
