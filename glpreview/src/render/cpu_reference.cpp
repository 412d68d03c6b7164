#include "glpreview/render/cpu_reference.hpp"

#include <algorithm>
#include <cmath>
#include <optional>
#include <stdexcept>
#include <string>
#include <thread>

#include "glpreview/render/mirror_path.hpp"
#include "glpreview/render/sphere_intersection.hpp"
#include "glpreview/render/worker_threads.hpp"
#include "glpreview/scene/camera.hpp"

namespace metalfit::glpreview {

ReferenceRender render_mirror_paths(const Scene& scene, const EnvironmentTracer& environment, int max_bounces,
                                    int threads, const CpuLighting* lighting,
                                    const std::function<RGB(const MirrorPath& path, const RGB& light)>& shade) {
    const int w = scene.width, h = scene.height;
    ReferenceRender out{Image(w, h), std::vector<int>(static_cast<std::size_t>(w) * h, -1)};
    const CameraBasis basis = camera_basis(scene.camera, w, h);
    if (max_bounces < 1 || max_bounces > kMaxPathBounces)
        throw std::invalid_argument("render_reference: max_bounces " + std::to_string(max_bounces) + " outside 1-" +
                                    std::to_string(kMaxPathBounces));
    for_each_pixel(w, h, threads, [&](int px, int py, int row) {
        const Vec3 d = camera_ray(basis, px, py, w, h);
        const SphereHit hit = nearest_sphere(scene.spheres, basis.position, d);
        // An emitter an effect puts in the room (a sphere light) is seen before the environment.
        const auto seen = [&](Vec3 origin, Vec3 direction) {
            if (lighting && lighting->emitter)
                if (const std::optional<RGB> emitted = lighting->emitter(origin, direction)) return *emitted;
            return environment.trace(origin, direction).radiance;
        };
        RGB radiance;
        if (hit.sphere < 0) {
            radiance = seen(basis.position, d);
        } else {
            const MirrorPath path = mirror_path(scene.spheres, basis.position, d, hit, max_bounces);
            radiance = shade(path, seen(path.origin, path.direction));
        }
        out.image.set(px, row, radiance);
        out.sphere_id[static_cast<std::size_t>(row) * w + px] = hit.sphere;
    });
    return out;
}

ReferenceRender render_reference(const Scene& scene, const std::vector<const SphereFresnel*>& fresnel,
                                 const EnvironmentTracer& environment, int threads, const CpuLighting* lighting,
                                 int max_bounces) {
    return render_mirror_paths(
        scene, environment, max_bounces, threads, lighting, [&fresnel](const MirrorPath& path, const RGB& light) {
            RGB throughput = (*fresnel[static_cast<std::size_t>(path.bounces[0].sphere)])(path.bounces[0].mu);
            for (int k = 1; k < path.count; ++k) {
                const MirrorBounce& b = path.bounces[static_cast<std::size_t>(k)];
                throughput = throughput * (*fresnel[static_cast<std::size_t>(b.sphere)])(b.mu);
            }
            return throughput * light;
        });
}

}  // namespace metalfit::glpreview
