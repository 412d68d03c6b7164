#include "cpu_lights.hpp"

#include <algorithm>
#include <cmath>
#include <numbers>
#include <random>

#include "glpreview/effects/registry.hpp"
#include "glpreview/render/ggx.hpp"

namespace metalfit::glpreview {
namespace {

constexpr double kPi = std::numbers::pi;
constexpr double kShadowEpsilon = 1e-6;

// Light i's unit direction l from p, its irradiance E normal to l (unshadowed) and its distance (∞: directional),
// as lights_at() in lights.glsl; sphere lights as a point of their power (the room integrates them, see below).
void light_at(const Light& light, Vec3 p, Vec3& l, RGB& E, double& dist) {
    if (light.type == LightType::directional) {
        l = -light.direction;
        E = light.power();
        dist = std::numeric_limits<double>::infinity();
        return;
    }
    const Vec3 to = light.position - p;
    const double d2 = dot(to, to);
    dist = std::sqrt(d2);
    l = (1.0 / dist) * to;
    if (light.type == LightType::sphere) {
        E = (kPi * light.radius * light.radius / d2) * light.power();
        return;
    }
    E = (1.0 / d2) * light.power();
    if (light.type == LightType::spot) E = spot_weight(light, dot(-l, light.direction)) * E;
}

// A unit vector of the cone around axis w with cos of its half angle cos_max, for (u1, u2) ∈ [0, 1)² (uniform
// in solid angle).
Vec3 cone_direction(Vec3 w, double cos_max, double u1, double u2) {
    const double cos_t = 1.0 - u1 * (1.0 - cos_max);
    const double sin_t = std::sqrt(std::max(0.0, 1.0 - cos_t * cos_t));
    const double phi = 2 * kPi * u2;
    const ggx::Frame frame(w);
    return normalize(frame.to_world({sin_t * std::cos(phi), sin_t * std::sin(phi), cos_t}));
}

// The cone a sphere light subtends from p: its axis, the cos of its half angle and its solid angle.
struct LightCone {
    Vec3 axis;
    double cos_max = 1, solid_angle = 0;

    LightCone(const Light& light, Vec3 p) {
        const Vec3 to = light.position - p;
        const double d = length(to);
        axis = (1.0 / d) * to;
        cos_max = std::sqrt(std::max(0.0, 1.0 - light.radius * light.radius / (d * d)));
        solid_angle = 2 * kPi * (1 - cos_max);
    }
    // A direction of the cone for (u1, u2) ∈ [0, 1)², uniform in solid angle.
    Vec3 direction(double u1, double u2) const { return cone_direction(axis, cos_max, u1, u2); }
};

// Where a ray from p along unit dir meets the sphere light (its first hit), or ∞.
double light_distance(const Light& light, Vec3 p, Vec3 dir) {
    const Vec3 oc = p - light.position;
    const double b = dot(oc, dir);
    const double h = b * b - (dot(oc, oc) - light.radius * light.radius);
    if (h < 0) return std::numeric_limits<double>::infinity();
    return -b - std::sqrt(h);
}

}  // namespace

double spot_weight(const Light& light, double cos_angle) {
    const double to_radians = kPi / 180;
    const double e0 = std::cos(light.cone_outer_deg * to_radians);
    const double e1 = std::max(std::cos(light.cone_inner_deg * to_radians), e0 + 1e-6);
    const double t = std::clamp((cos_angle - e0) / (e1 - e0), 0.0, 1.0);
    return t * t * (3 - 2 * t);
}

bool occluded(const Scene& scene, Vec3 o, Vec3 d, double t_max, std::optional<std::size_t> skip) {
    if (occluded_by_spheres_and_boxes(scene, o, d, t_max, skip)) return true;
    // The objects effects stand in the room (the rings: ENVIRONMENT_OCCLUDER in the shadow maps).
    for (const Effect* effect : all_effects())
        if (effect->cpu_occluder(scene, o, d) < t_max) return true;
    return false;
}

bool occluded_by_spheres_and_boxes(const Scene& scene, Vec3 o, Vec3 d, double t_max, std::optional<std::size_t> skip) {
    for (std::size_t i = 0; i < scene.spheres.size(); ++i) {
        if (skip && *skip == i) continue;
        const Sphere& s = scene.spheres[i];
        const Vec3 oc = o - s.center;
        const double b = dot(oc, d);
        const double h = b * b - (dot(oc, oc) - s.radius * s.radius);
        if (h < 0) continue;
        const double t = -b - std::sqrt(h);
        if (t > kShadowEpsilon && t < t_max) return true;
    }
    for (const RoomBox& box : scene.environment.room.boxes) {
        double t_near = -std::numeric_limits<double>::infinity(), t_far = std::numeric_limits<double>::infinity();
        for (int i = 0; i < 3; ++i) {
            const double inv = 1.0 / (std::abs(d[i]) < 1e-12 ? (d[i] < 0 ? -1e-12 : 1e-12) : d[i]);
            const double t1 = (box.min[i] - o[i]) * inv, t2 = (box.max[i] - o[i]) * inv;
            t_near = std::max(t_near, std::min(t1, t2));
            t_far = std::min(t_far, std::max(t1, t2));
        }
        if (t_near <= t_far && t_near > kShadowEpsilon && t_near < t_max) return true;
    }
    return false;
}

RGB light_on_surface(const Scene& scene, const Lights& lights, const RGB& albedo, Vec3 p, Vec3 n) {
    RGB sum{0, 0, 0};
    for (const Light& light : lights.lights) {
        if (light.type == LightType::sphere) {
            // ∫ L cos θ V dω over the light's cone: a fixed spiral of 64 directions (uniform in solid angle).
            const LightCone cone(light, p);
            constexpr int kSpiral = 64;
            double visible_cos = 0;
            for (int k = 0; k < kSpiral; ++k) {
                const double u1 = (k + 0.5) / kSpiral, u2 = std::fmod(k * 0.6180339887498949, 1.0);
                const Vec3 dir = cone.direction(u1, u2);
                const double cos_i = dot(n, dir);
                if (cos_i <= 0) continue;
                if (!occluded(scene, p, dir, light_distance(light, p, dir))) visible_cos += cos_i;
            }
            sum = sum + (cone.solid_angle * visible_cos / kSpiral) * light.power();
            continue;
        }
        Vec3 l;
        RGB E;
        double dist = 0;
        light_at(light, p, l, E, dist);
        const double n_l = dot(n, l);
        if (n_l <= 0 || occluded(scene, p, l, dist)) continue;
        sum = sum + n_l * E;
    }
    return (1.0 / kPi) * RGB{albedo.r * sum.r, albedo.g * sum.g, albedo.b * sum.b};
}

std::optional<RGB> emitter_seen(const Lights& lights, Vec3 origin, Vec3 dir) {
    double best = std::numeric_limits<double>::infinity();
    std::optional<RGB> seen;
    for (const Light& light : lights.lights) {
        if (light.type != LightType::sphere) continue;
        const double t = light_distance(light, origin, dir);
        if (t > 0 && t < best) {
            best = t;
            seen = light.power();
        }
    }
    return seen;
}

RadianceEstimate specular_from_lights(const Scene& scene, const Lights& lights, std::size_t sphere, Vec3 p, Vec3 n,
                                      Vec3 v, const SphereFresnel& fresnel, int samples, std::uint64_t seed) {
    const double alpha = std::max(ggx::alpha(scene.spheres[sphere].roughness), 1e-3);
    const ggx::Frame frame(n);
    Vec3 v_local = frame.to_local(v);
    v_local.z = std::max(v_local.z, 1e-4);
    v_local = normalize(v_local);
    // f_r cos θ_l for light direction l (world), the sphere's own Fresnel at v·h.
    const auto brdf_cos = [&](Vec3 l) -> RGB {
        const Vec3 l_local = frame.to_local(l);
        if (l_local.z <= 0) return {0, 0, 0};
        const Vec3 h = normalize(v_local + l_local);
        const double value = ggx::distribution(h, alpha) * ggx::smith_g2(v_local, l_local, alpha) / (4 * v_local.z);
        return value * fresnel(std::clamp(dot(v_local, h), 0.0, 1.0));
    };
    RadianceEstimate result;
    std::mt19937_64 random(seed);
    std::uniform_real_distribution<double> uniform(0.0, 1.0);
    for (const Light& light : lights.lights) {
        if (light.type == LightType::sphere) {
            const LightCone cone(light, p);
            const double solid_angle = cone.solid_angle;
            RGB sum{0, 0, 0}, sum2{0, 0, 0};
            for (int k = 0; k < samples; ++k) {
                const Vec3 dir = cone.direction(uniform(random), uniform(random));
                if (dot(n, dir) <= 0 || occluded(scene, p, dir, light_distance(light, p, dir), sphere)) continue;
                const RGB f = brdf_cos(dir);
                const RGB x{solid_angle * f.r * light.power().r, solid_angle * f.g * light.power().g,
                            solid_angle * f.b * light.power().b};
                sum = sum + x;
                sum2 = sum2 + RGB{x.r * x.r, x.g * x.g, x.b * x.b};
            }
            for (int c = 0; c < 3; ++c) {
                const double mean = sum[c] / samples;
                const double variance =
                    samples > 1 ? std::max(0.0, (sum2[c] - samples * mean * mean) / (samples - 1)) : 0.0;
                result.mean[c] += mean;
                result.variance[c] += variance / samples;
            }
            continue;
        }
        Vec3 l;
        RGB E;
        double dist = 0;
        light_at(light, p, l, E, dist);
        if (dot(n, l) <= 0 || occluded(scene, p, l, dist, sphere)) continue;
        const RGB f = brdf_cos(l);
        result.mean = result.mean + RGB{f.r * E.r, f.g * E.g, f.b * E.b};
    }
    return result;
}

}  // namespace metalfit::glpreview
