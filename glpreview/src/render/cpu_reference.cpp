#include "glpreview/render/cpu_reference.hpp"

#include <algorithm>
#include <cmath>
#include <thread>

#include "glpreview/render/worker_threads.hpp"
#include "glpreview/scene/camera.hpp"

namespace metalfit::glpreview {

ReferenceRender render_reference(const Scene& scene, const std::vector<const SphereFresnel*>& fresnel,
                                 const EnvironmentTracer& environment, int threads, const CpuLighting* lighting) {
    const int w = scene.width, h = scene.height;
    ReferenceRender out{Image(w, h), std::vector<int>(static_cast<std::size_t>(w) * h, -1)};
    const CameraBasis basis = camera_basis(scene.camera, w, h);
    for_each_pixel(w, h, threads, [&](int px, int py, int row) {
        const Vec3 d = camera_ray(basis, px, py, w, h);
        int nearest = -1;
        double t_nearest = std::numeric_limits<double>::infinity();
        for (std::size_t s = 0; s < scene.spheres.size(); ++s) {
            const Sphere& sphere = scene.spheres[s];
            const Vec3 oc = basis.position - sphere.center;
            const double b = dot(oc, d);
            const double disc = b * b - (dot(oc, oc) - sphere.radius * sphere.radius);
            if (disc < 0) continue;
            const double t = -b - std::sqrt(disc);
            if (t > 0 && t < t_nearest) {
                t_nearest = t;
                nearest = static_cast<int>(s);
            }
        }
        // An emitter an effect puts in the room (a sphere light) is seen before the environment.
        const auto seen = [&](Vec3 origin, Vec3 direction) {
            if (lighting && lighting->emitter)
                if (const std::optional<RGB> emitted = lighting->emitter(origin, direction)) return *emitted;
            return environment.trace(origin, direction).radiance;
        };
        RGB radiance;
        if (nearest < 0) {
            radiance = seen(basis.position, d);
        } else {
            const Sphere& sphere = scene.spheres[static_cast<std::size_t>(nearest)];
            const Vec3 p = basis.position + t_nearest * d;
            const Vec3 n = (1.0 / sphere.radius) * (p - sphere.center);
            const double mu = std::clamp(-dot(d, n), 0.0, 1.0);
            const Vec3 r = normalize(reflect(d, n));
            const RGB f = (*fresnel[static_cast<std::size_t>(nearest)])(mu);
            radiance = f * seen(p, r);
        }
        out.image.set(px, row, radiance);
        out.sphere_id[static_cast<std::size_t>(row) * w + px] = nearest;
    });
    return out;
}

}  // namespace metalfit::glpreview
