// The path of a camera ray through mirror reflections between the spheres (the CPU references with max_bounces):
// the ray enters the sphere it hits first, reflects about its normal (μ = cos θ of that bounce), and the reflected
// ray is intersected exactly with the other spheres; up to `max_bounces` reflections. The last reflected ray — the
// max_bounces-th, or an earlier one that meets no sphere — is the one that takes the environment's radiance. Rough
// spheres are mirrors here (the Monte-Carlo reference samples their lobes).
#pragma once

#include <array>

#include "glpreview/render/sphere_intersection.hpp"
#include "glpreview/scene/scene.hpp"

namespace metalfit::glpreview {

inline constexpr int kMaxPathBounces = 8;  // the scene key's upper bound (docs/scene.md, max_bounces)

struct MirrorBounce {
    int sphere = -1;  // the sphere reflecting
    double mu = 0;    // cos θ of the incident ray against its normal, in [0, 1]
};

struct MirrorPath {
    std::array<MirrorBounce, kMaxPathBounces> bounces{};
    int count = 0;   // bounces used (≥ 1)
    Vec3 origin;     // the last reflected ray: from the last bounce's point …
    Vec3 direction;  // … along this unit direction
};

// The path of the ray origin + t·d (unit d) whose first hit is `first` (a sphere, t > 0). Throws
// std::invalid_argument when max_bounces is outside 1 … kMaxPathBounces.
MirrorPath mirror_path(const std::vector<Sphere>& spheres, Vec3 origin, Vec3 d, SphereHit first, int max_bounces);

}  // namespace metalfit::glpreview
