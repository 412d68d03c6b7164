// The reflection lookup of mirror and prefiltered spheres: where a reflected ray meets the captured environment —
// classic (the direction alone), box-parallax, or the distance impostor's search with its root finder
// (reflection.glsl; thesis ch. 4). Its probe (effects/reflection_lookup.hpp) runs the same GLSL for given rays.
#pragma once

#include "glpreview/effects/effect.hpp"
#include "glpreview/effects/reflection_lookup.hpp"

namespace metalfit::glpreview {

const Effect& reflection_effect();

}  // namespace metalfit::glpreview
