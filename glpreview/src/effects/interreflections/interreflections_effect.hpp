// Inter-reflections between spheres (the scene key max_bounces): per-sphere distance maps taken from each mirror
// sphere's centre, holding the room and the other spheres, iterated once per extra bounce (docs/preview.md,
// "Inter-reflections").
#pragma once

#include "glpreview/effects/effect.hpp"

namespace metalfit::glpreview {

const Effect& interreflections_effect();

}  // namespace metalfit::glpreview
