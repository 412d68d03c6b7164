#include "glpreview/render/sphere_intersection.hpp"

#include <cmath>

namespace metalfit::glpreview {

SphereHit nearest_sphere(const std::vector<Sphere>& spheres, Vec3 origin, Vec3 dir, int exclude) {
    SphereHit hit;
    for (std::size_t s = 0; s < spheres.size(); ++s) {
        if (static_cast<int>(s) == exclude) continue;
        const Sphere& sphere = spheres[s];
        const Vec3 oc = origin - sphere.center;
        const double b = dot(oc, dir);
        const double disc = b * b - (dot(oc, oc) - sphere.radius * sphere.radius);
        if (disc < 0) continue;
        const double t = -b - std::sqrt(disc);
        if (t > 0 && t < hit.t) {
            hit.t = t;
            hit.sphere = static_cast<int>(s);
        }
    }
    return hit;
}

}  // namespace metalfit::glpreview
