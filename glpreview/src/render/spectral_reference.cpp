#include "glpreview/render/spectral_reference.hpp"

#include "glpreview/render/mirror_path.hpp"

namespace metalfit::glpreview {

ReferenceRender render_spectral_reference(const Scene& scene, const std::vector<const SpectralFresnel*>& spectral,
                                          const RgbUplift& uplift, const EnvironmentTracer& environment,
                                          int max_bounces, int threads, const CpuLighting* lighting) {
    return render_mirror_paths(scene, environment, max_bounces, threads, lighting,
                               [&](const MirrorPath& path, const RGB& light) {
                                   std::vector<double> throughput(uplift.size(), 1.0);
                                   for (int k = 0; k < path.count; ++k) {
                                       const MirrorBounce& b = path.bounces[static_cast<std::size_t>(k)];
                                       spectral[static_cast<std::size_t>(b.sphere)]->multiply(b.mu, throughput);
                                   }
                                   return uplift.rgb(throughput, light);
                               });
}

}  // namespace metalfit::glpreview
