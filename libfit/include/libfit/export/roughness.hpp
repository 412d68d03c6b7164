// The surface roughness written with the Fresnel parameters (MaterialX, OpenPBR, JSON) and given to glpreview's
// spheres: perceptual, in [0, 1] — OpenPBR's specular_roughness; MaterialX's BSDFs receive it through
// roughness_anisotropy (α = R²), so both folders render the same lobe, and glpreview's GGX takes the same number.
#pragma once

#include <optional>
#include <string_view>

namespace metalfit {

// OpenPBR's own default.
inline constexpr double kDefaultRoughness = 0.3;
inline constexpr const char* kDefaultRoughnessText = "0.3";  // as --help and the docs print it

// "0.25" → 0.25: the whole text a decimal number in [0, 1]; nothing otherwise (each command line says so in its terms).
std::optional<double> roughness_from_text(std::string_view text);

}  // namespace metalfit
