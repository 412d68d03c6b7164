#include "glpreview/render/spectral_reference.hpp"

#include <optional>

#include "glpreview/render/mirror_path.hpp"
#include "glpreview/render/sphere_intersection.hpp"
#include "glpreview/render/worker_threads.hpp"
#include "glpreview/scene/camera.hpp"

namespace metalfit::glpreview {

ReferenceRender render_spectral_reference(const Scene& scene, const std::vector<const SpectralFresnel*>& spectral,
                                          const RgbUplift& uplift, const EnvironmentTracer& environment,
                                          int max_bounces, int threads, const CpuLighting* lighting) {
    const int w = scene.width, h = scene.height;
    ReferenceRender out{Image(w, h), std::vector<int>(static_cast<std::size_t>(w) * h, -1)};
    const CameraBasis basis = camera_basis(scene.camera, w, h);
    for_each_pixel(w, h, threads, [&](int px, int py, int row) {
        const Vec3 d = camera_ray(basis, px, py, w, h);
        const SphereHit hit = nearest_sphere(scene.spheres, basis.position, d);
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
            std::vector<double> throughput(uplift.size(), 1.0);
            for (int k = 0; k < path.count; ++k) {
                const MirrorBounce& b = path.bounces[static_cast<std::size_t>(k)];
                spectral[static_cast<std::size_t>(b.sphere)]->multiply(b.mu, throughput);
            }
            radiance = uplift.rgb(throughput, seen(path.origin, path.direction));
        }
        out.image.set(px, row, radiance);
        out.sphere_id[static_cast<std::size_t>(row) * w + px] = hit.sphere;
    });
    return out;
}

}  // namespace metalfit::glpreview
