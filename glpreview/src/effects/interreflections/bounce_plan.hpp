// Which spheres need a distance map of their own for inter-reflections, decided from the scene's geometry (not a
// flag): a mirror sphere (roughness 0) gets distance maps when max_bounces > 1 and it sees another sphere (no room box
// hides the other sphere from it); a rough sphere with the prefiltered lobe that sees another sphere gets a radiance
// map of its own, prefiltered (when some mirror is mapped). The plan says why, for --explain.
#pragma once

#include <cstddef>
#include <string>
#include <vector>

#include "glpreview/scene/scene.hpp"

namespace metalfit::glpreview {

struct BouncePlan {
    int max_bounces = 1;
    std::vector<std::size_t> mapped;        // the mirror spheres given distance maps, in scene order
    std::vector<std::size_t> rough_mapped;  // the rough (prefiltered) spheres given a prefiltered map of their own
    std::string reason;                     // why maps are made, or why none are

    bool active() const { return !mapped.empty() || !rough_mapped.empty(); }
    bool maps(std::size_t sphere) const;        // a mirror with distance maps
    bool maps_rough(std::size_t sphere) const;  // a rough sphere with a prefiltered map of its own
};

BouncePlan plan_bounces(const Scene& scene);

// Whether a room box hides sphere b from sphere a entirely (conservatively: the segment between their centres
// crosses the box shrunk on every side by the larger radius, so every line between the two spheres meets the box).
bool hidden_by_room(const Scene& scene, const Sphere& a, const Sphere& b);

}  // namespace metalfit::glpreview
