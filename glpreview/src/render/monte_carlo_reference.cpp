#include "glpreview/render/monte_carlo_reference.hpp"

#include <algorithm>
#include <cmath>
#include <random>
#include <stdexcept>
#include <string>
#include <thread>

#include "glpreview/render/cpu_lighting.hpp"
#include "glpreview/render/ggx.hpp"
#include "glpreview/render/mirror_path.hpp"
#include "glpreview/render/sphere_intersection.hpp"
#include "glpreview/render/worker_threads.hpp"
#include "glpreview/scene/camera.hpp"

namespace metalfit::glpreview {
namespace {

// The pixel (px, py) of a scene with max_bounces > 1: its path sampled `samples` times, each vertex a mirror
// reflection or a sample of the rough sphere's lobe (the same visible-normal sampling and weight as one bounce), up
// to max_bounces. A pixel whose mirror path meets no rough sphere keeps the analytic reference's value (exact).
void estimate_bounces(const Scene& scene, const std::vector<const SphereFresnel*>& fresnel,
                      const EnvironmentTracer& environment, const CameraBasis& basis, int px, int py, int row,
                      int samples, const CpuLighting* lighting, int max_bounces, MonteCarloReference& out) {
    const int w = scene.width, h = scene.height;
    const Vec3 d0 = camera_ray(basis, px, py, w, h);
    const SphereHit first = nearest_sphere(scene.spheres, basis.position, d0);
    if (first.sphere < 0) return;
    const MirrorPath mirror = mirror_path(scene.spheres, basis.position, d0, first, max_bounces);
    bool reaches_rough = false;
    for (int k = 0; k < mirror.count; ++k)
        reaches_rough = reaches_rough || scene.spheres[static_cast<std::size_t>(mirror.bounces[k].sphere)].rough();
    if (!reaches_rough) return;
    std::mt19937_64 random(kMonteCarloSeed ^ (0x9E3779B97F4A7C15ull * (static_cast<std::uint64_t>(row) * w + px + 1)));
    std::uniform_real_distribution<double> uniform(0.0, 1.0);
    double sum[3] = {0, 0, 0}, sum2[3] = {0, 0, 0};
    for (int k = 0; k < samples; ++k) {
        Vec3 origin = basis.position, d = d0;
        SphereHit hit = first;
        RGB throughput{1, 1, 1};
        Vec3 p = origin;
        for (int bounce = 1;; ++bounce) {
            const std::size_t s = static_cast<std::size_t>(hit.sphere);
            const Sphere& sphere = scene.spheres[s];
            p = origin + hit.t * d;
            const Vec3 n = (1.0 / sphere.radius) * (p - sphere.center);
            if (sphere.rough()) {
                const ggx::Frame frame(n);
                Vec3 v = frame.to_local(-d);
                v.z = std::max(v.z, 1e-6);
                v = normalize(v);
                const double u1 = uniform(random), u2 = uniform(random);
                const ggx::LobeSample l = ggx::sample_reflection(v, ggx::alpha(sphere.roughness), u1, u2);
                if (l.weight <= 0) {
                    throughput = RGB{0, 0, 0};
                    break;
                }
                throughput = throughput * (l.weight * (*fresnel[s])(l.cos_d));
                d = normalize(frame.to_world(l.l));
            } else {
                throughput = throughput * (*fresnel[s])(std::clamp(-dot(d, n), 0.0, 1.0));
                d = normalize(reflect(d, n));
            }
            if (bounce == max_bounces) break;
            const SphereHit next = nearest_sphere(scene.spheres, p, d, hit.sphere);
            if (next.sphere < 0) break;
            origin = p;
            hit = next;
        }
        const RGB radiance = throughput * environment.trace(p, d).radiance;
        for (int c = 0; c < 3; ++c) {
            sum[c] += radiance[c];
            sum2[c] += radiance[c] * radiance[c];
        }
    }
    const Sphere& sphere = scene.spheres[static_cast<std::size_t>(first.sphere)];
    RadianceEstimate direct;  // the light effects add at the first vertex (lights), with its own variance
    const bool lit = lighting && lighting->sphere_light && sphere.rough();
    if (lit) {
        const Vec3 p = basis.position + first.t * d0;
        const Vec3 n = (1.0 / sphere.radius) * (p - sphere.center);
        direct = lighting->sphere_light(
            static_cast<std::size_t>(first.sphere), p, n, -d0, *fresnel[static_cast<std::size_t>(first.sphere)],
            samples, kMonteCarloSeed ^ (0xD1B54A32D192ED03ull * (static_cast<std::uint64_t>(row) * w + px + 1)));
    }
    RGB mean, error;
    for (int c = 0; c < 3; ++c) {
        mean[c] = sum[c] / samples;
        const double variance =
            samples > 1 ? std::max(0.0, (sum2[c] - samples * mean[c] * mean[c]) / (samples - 1)) : 0.0;
        error[c] = std::sqrt(variance / samples + (lit ? direct.variance[c] : 0.0));
        if (lit) mean[c] += direct.mean[c];
    }
    out.render.image.set(px, row, mean);
    out.standard_error.set(px, row, error);
}

}  // namespace

MonteCarloReference render_monte_carlo_reference(const Scene& scene, const std::vector<const SphereFresnel*>& fresnel,
                                                 const EnvironmentTracer& environment, const ReferenceRender& analytic,
                                                 int samples, int threads, const CpuLighting* lighting,
                                                 int max_bounces) {
    const int w = scene.width, h = scene.height;
    MonteCarloReference out{analytic, Image(w, h)};
    const CameraBasis basis = camera_basis(scene.camera, w, h);
    if (max_bounces < 1 || max_bounces > kMaxPathBounces)
        throw std::invalid_argument("render_monte_carlo_reference: max_bounces " + std::to_string(max_bounces) +
                                    " outside 1-" + std::to_string(kMaxPathBounces));
    for_each_pixel(w, h, threads, [&](int px, int py, int row) {
        const int id = analytic.sphere_id[static_cast<std::size_t>(row) * w + px];
        if (id < 0) return;
        const Sphere& sphere = scene.spheres[static_cast<std::size_t>(id)];
        if (max_bounces > 1) {
            estimate_bounces(scene, fresnel, environment, basis, px, py, row, samples, lighting, max_bounces, out);
            return;
        }
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
