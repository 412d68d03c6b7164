// Rings (the scene key "rings"): concave metal reflectors standing in the room, mirrors drawn into every program that
// reads the environment (the capture, the background, the shadow maps, the spheres' reflections), each with its
// material's Fresnel (docs/scene.md, "Rings"). The caustics effect throws their light onto the room.
#pragma once

#include "glpreview/effects/effect.hpp"

namespace metalfit::glpreview {

const Effect& rings_effect();

}  // namespace metalfit::glpreview
