// Caustics (docs/preview.md, "Caustics"): the light a mirror ring throws onto the room, by the distance-impostor
// article's caustic maps: per light and ring, photons from the light's view reflected by the ring with its Fresnel,
// their hits found in the room's distance cube and splatted with a Gaussian into the room's light maps, which every
// program that reads the environment adds to the room's surfaces.
#pragma once

#include "glpreview/effects/effect.hpp"

namespace metalfit::glpreview {

const Effect& caustics_effect();

}  // namespace metalfit::glpreview
