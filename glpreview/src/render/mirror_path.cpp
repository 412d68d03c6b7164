#include "glpreview/render/mirror_path.hpp"

#include <algorithm>
#include <stdexcept>
#include <string>

namespace metalfit::glpreview {

MirrorPath mirror_path(const std::vector<Sphere>& spheres, Vec3 origin, Vec3 d, SphereHit first, int max_bounces) {
    if (max_bounces < 1 || max_bounces > kMaxPathBounces)
        throw std::invalid_argument("mirror_path: max_bounces " + std::to_string(max_bounces) + " outside 1-" +
                                    std::to_string(kMaxPathBounces));
    MirrorPath path;
    SphereHit hit = first;
    for (;;) {
        // The same expressions as the one-bounce reference always had, so that max_bounces = 1 changes no bit.
        const Sphere& sphere = spheres[static_cast<std::size_t>(hit.sphere)];
        const Vec3 p = origin + hit.t * d;
        const Vec3 n = (1.0 / sphere.radius) * (p - sphere.center);
        const double mu = std::clamp(-dot(d, n), 0.0, 1.0);
        const Vec3 r = normalize(reflect(d, n));
        path.bounces[static_cast<std::size_t>(path.count++)] = {hit.sphere, mu};
        path.origin = p;
        path.direction = r;
        if (path.count == max_bounces) return path;
        const SphereHit next = nearest_sphere(spheres, p, r, hit.sphere);
        if (next.sphere < 0) return path;
        origin = p;
        d = r;
        hit = next;
    }
}

}  // namespace metalfit::glpreview
