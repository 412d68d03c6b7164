// The localization frame (localization.exr, the localization benchmark): instead of radiance, each sphere writes
// the distance impostor's refinement steps taken and |ρ − 1| at its lookup point.
#pragma once

#include "glpreview/effects/effect.hpp"

namespace metalfit::glpreview {

const Effect& localization_diagnostics_effect();

}  // namespace metalfit::glpreview
