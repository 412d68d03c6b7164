// A layered material's optics on the colour grid: per wavelength of the colorimetry's 1 nm grid, the metal's, the
// film's and the coat's indices and the film's and coat's thicknesses in the form of optics/stack_reflectance.hpp,
// with the coverage checks that name the layer's file.
#pragma once

#include <string>
#include <vector>

#include "libfit/io/layer_stack.hpp"
#include "libfit/optics/stack_reflectance.hpp"
#include "libfit/reference/reference_curve.hpp"

namespace metalfit {

// Throws InputError naming the layer's file (or the constant) when a film's or coat's n or k does not cover `needed`
// (unless `options` extrapolate): which part is missing, and that --extrapolate holds the end values; and when the
// coat's n is below 1 at a nanometre of `needed`.
void require_layer_coverage(const LayerStack& layers, const WavelengthRange& needed, const SpectralOptions& options);

// StackOptics at every wavelength of `grid_first_nm`..`grid_last_nm` for `metal` and its layers (which it must
// have). A coat whose table gives n < 1 somewhere on the grid: InputError naming the file and the wavelength.
std::vector<StackOptics<double>> stack_optics_on_grid(const Material& metal, int grid_first_nm, int grid_last_nm,
                                                      const SpectralOptions& options);

// The layers' held_constant_ranges, each prefixed with the layer ("film TiO2 (Siefke): k held at …").
std::vector<std::string> layer_held_constant(const LayerStack& layers, const WavelengthRange& needed,
                                             const SpectralOptions& options);

}  // namespace metalfit
