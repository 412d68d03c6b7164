#include "glpreview/render/monte_carlo_reference.hpp"

#include <algorithm>
#include <cmath>
#include <random>
#include <thread>

#include "glpreview/render/cpu_lighting.hpp"
#include "glpreview/render/ggx.hpp"
#include "glpreview/render/worker_threads.hpp"
#include "glpreview/scene/camera.hpp"

namespace metalfit::glpreview {

MonteCarloReference render_monte_carlo_reference(const Scene& scene, const std::vector<const SphereFresnel*>& fresnel,
                                                 const EnvironmentTracer& environment, const ReferenceRender& analytic,
                                                 int samples, int threads, const CpuLighting* lighting) {
    const int w = scene.width, h = scene.height;
    MonteCarloReference out{analytic, Image(w, h)};
    const CameraBasis basis = camera_basis(scene.camera, w, h);
    for_each_pixel(w, h, threads, [&](int px, int py, int row) {
        const int id = analytic.sphere_id[static_cast<std::size_t>(row) * w + px];
        if (id < 0) return;
        const Sphere& sphere = scene.spheres[static_cast<std::size_t>(id)];
        if (!sphere.rough()) return;
        const SphereFresnel& f = *fresnel[static_cast<std::size_t>(id)];
        const Vec3 d = camera_ray(basis, px, py, w, h);
        const Vec3 oc = basis.position - sphere.center;
        const double b = dot(oc, d);
        const double t = -b - std::sqrt(std::max(0.0, b * b - (dot(oc, oc) - sphere.radius * sphere.radius)));
        const Vec3 p = basis.position + t * d;
        const Vec3 n = (1.0 / sphere.radius) * (p - sphere.center);
        const ggx::Frame frame(n);
        Vec3 v = frame.to_local(-d);
        v.z = std::max(v.z, 1e-6);
        v = normalize(v);
        const double alpha = ggx::alpha(sphere.roughness);
        std::mt19937_64 random(kMonteCarloSeed ^
                               (0x9E3779B97F4A7C15ull * (static_cast<std::uint64_t>(row) * w + px + 1)));
        std::uniform_real_distribution<double> uniform(0.0, 1.0);
        double sum[3] = {0, 0, 0}, sum2[3] = {0, 0, 0};
        for (int k = 0; k < samples; ++k) {
            const double u1 = uniform(random), u2 = uniform(random);
            const ggx::LobeSample s = ggx::sample_reflection(v, alpha, u1, u2);
            if (s.weight <= 0) continue;
            const RGB fresnel_value = f(s.cos_d);
            const RGB radiance = environment.trace(p, normalize(frame.to_world(s.l))).radiance;
            for (int c = 0; c < 3; ++c) {
                const double x = s.weight * fresnel_value[c] * radiance[c];
                sum[c] += x;
                sum2[c] += x * x;
            }
        }
        RadianceEstimate direct;  // the light effects add (lights), with its own variance
        const bool lit = lighting && lighting->sphere_light;
        if (lit)
            direct = lighting->sphere_light(
                static_cast<std::size_t>(id), p, n, -d, f, samples,
                kMonteCarloSeed ^ (0xD1B54A32D192ED03ull * (static_cast<std::uint64_t>(row) * w + px + 1)));
        RGB mean, error;
        for (int c = 0; c < 3; ++c) {
            mean[c] = sum[c] / samples;
            const double variance =
                samples > 1 ? std::max(0.0, (sum2[c] - samples * mean[c] * mean[c]) / (samples - 1)) : 0.0;
            error[c] = std::sqrt(lit ? variance / samples + direct.variance[c] : variance / samples);
            if (lit) mean[c] += direct.mean[c];
        }
        out.render.image.set(px, row, mean);
        out.standard_error.set(px, row, error);
    });
    return out;
}

}  // namespace metalfit::glpreview
