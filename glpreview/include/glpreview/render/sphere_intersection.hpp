// The nearest sphere a ray meets: the exact ray–sphere intersection of the CPU references (the camera's rays and,
// with max_bounces > 1, the rays reflected from one sphere towards the others).
#pragma once

#include <limits>
#include <vector>

#include "glpreview/scene/scene.hpp"
#include "glpreview/scene/vec3.hpp"

namespace metalfit::glpreview {

struct SphereHit {
    int sphere = -1;                                     // index into the scene's spheres; −1: none
    double t = std::numeric_limits<double>::infinity();  // ray parameter of the entry point
};

// The sphere whose entry point t > 0 along origin + t·dir (unit dir) comes first, skipping `exclude` (the sphere a
// reflected ray leaves; −1 for none). Spheres the origin lies inside are not hit (their entry point is behind it).
SphereHit nearest_sphere(const std::vector<Sphere>& spheres, Vec3 origin, Vec3 dir, int exclude = -1);

}  // namespace metalfit::glpreview
