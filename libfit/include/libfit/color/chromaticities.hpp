// The CIE xy chromaticities of an RGB working space's primaries and white, found through OCIO (RGB (1, 0, 0),
// (0, 1, 0), (0, 0, 1) and (1, 1, 1) of the space to CIE XYZ): what an OpenEXR file's `chromaticities` attribute
// holds, so that a reader knows which RGB the pixels are.
#pragma once

#include <array>

#include "libfit/color/color_space.hpp"

namespace metalfit {

struct Chromaticities {
    std::array<double, 2> red, green, blue, white;  // CIE 1931 x, y
};

Chromaticities chromaticities_of(const ColorSpaceConverter& space);

}  // namespace metalfit
