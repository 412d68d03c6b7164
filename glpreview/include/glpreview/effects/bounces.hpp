// The interreflections effect's setting (src/effects/interreflections/), read by the references too: how many times
// light may bounce between the scene's reflective spheres before it reaches the camera (the scene key `max_bounces`,
// docs/scene.md): 1 (the default) is a sphere reflecting the environment alone, as before; k > 1 lets a reflected
// ray hit another sphere and reflect again, up to k reflections along the path.
#pragma once

#include "glpreview/scene/scene.hpp"

namespace metalfit::glpreview {

inline constexpr int kMaxBounces = 8;
// The most mirror spheres a scene with max_bounces > 1 may have: each gets a map of three 256² cube-map layers
// (19 MB of RGBA32F), 16 of them 300 MB.
inline constexpr long kMaxMappedSpheres = 16;

struct Interreflections {
    int max_bounces = 1;
};

// The scene's max_bounces (1 when the scene does not give it).
int max_bounces(const Scene& scene);

}  // namespace metalfit::glpreview
