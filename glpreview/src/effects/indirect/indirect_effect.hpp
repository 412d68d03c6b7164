// Indirect light (the scene key "indirect"): the diffuse light the room reflects once more, by the virtual light
// sources of Lazányi's thesis, ch. 6 — light paths shot from the lights on the CPU, gathered by every program that
// reads the environment with the thesis's priority scheme for its shadow rays; the CPU reference gathers the same
// light by Monte Carlo (docs/preview.md, "Indirect light: virtual light sources").
#pragma once

#include "glpreview/effects/effect.hpp"

namespace metalfit::glpreview {

const Effect& indirect_effect();

}  // namespace metalfit::glpreview
