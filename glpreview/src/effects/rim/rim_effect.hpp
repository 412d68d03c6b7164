// The grazing-rim view (outputs.rim, off by default: rim.png, render/rim_view): each sphere's outer 10 % of the
// radius unwrapped beside its Fresnel curves at the rim's μ. Reads the beauty frame, the traced reference and, where
// the fit-error effect made it, the frame with the exact curves.
#pragma once

#include "glpreview/effects/effect.hpp"

namespace metalfit::glpreview {

const Effect& rim_effect();

}  // namespace metalfit::glpreview
