// Lights (docs/preview.md, "Lights"; docs/scene.md, "Lights"): point, spot, directional and sphere lights in a room,
// with soft shadows (distance maps + PCSS) on the room and on the spheres, the direct specular of rough spheres, and
// sphere lights seen by camera and mirror rays; the CPU reference traces the same light with exact shadow rays.
#pragma once

#include "glpreview/effects/effect.hpp"

namespace metalfit::glpreview {

const Effect& lights_effect();

}  // namespace metalfit::glpreview
