// A model's error apart from the localization's (docs/preview.md, "Fit error apart from localization"): the beauty
// frame again with every sphere's Fresnel the exact reference curve of its material (reference-lut-frame: the same
// lookup, lobes and lights, so both share the localization), and the signed false-colour views of the fit error
// (beauty against that frame: fit-error.png, fit-error.exr) and of the total error (beauty against the traced
// reference: error.png). Runs only where some sphere uses a libfit model and difference or metrics is asked for.
#pragma once

#include "glpreview/effects/effect.hpp"

namespace metalfit::glpreview {

const Effect& fit_error_effect();

}  // namespace metalfit::glpreview
