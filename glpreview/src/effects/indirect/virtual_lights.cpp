#include "virtual_lights.hpp"

#include <algorithm>
#include <cmath>
#include <functional>
#include <numbers>
#include <optional>

#include "../lights/cpu_lights.hpp"
#include "../lights/light.hpp"
#include "../rings/ring.hpp"
#include "glpreview/render/environment.hpp"
#include "glpreview/render/sphere_fresnel.hpp"
#include "glpreview/render/sphere_intersection.hpp"

namespace metalfit::glpreview {
namespace {

constexpr double kPi = std::numbers::pi;
constexpr int kMaxRingReflections = 4;

// Where a ray first meets the room's walls, floor, ceiling or boxes, and that surface's albedo (its colour clamped
// to 1, as environment.glsl's lit surfaces take it); none for a ceiling panel (an emitter) or no hit.
struct RoomSurface {
    double t = 0;
    Vec3 point, normal;
    RGB albedo;
    bool diffuse = false;
};
RoomSurface room_surface(const Environment& environment, Vec3 o, Vec3 d) {
    RoomSurface s;
    // The tracer hands each lit surface's albedo, point and normal to its light: recorded here, nothing added.
    const EnvironmentTracer tracer(environment, nullptr, [&s](const RGB& albedo, Vec3 p, Vec3 n) {
        s.albedo = albedo;
        s.point = p;
        s.normal = n;
        s.diffuse = true;
        return RGB{0, 0, 0};
    });
    s.t = tracer.trace(o, d).t;
    return s;
}

RGB times(const RGB& a, const RGB& b) { return {a.r * b.r, a.g * b.g, a.b * b.b}; }

// Follows one light path from o along d carrying `power` (W): rings reflect it, the first diffuse room surface keeps it.
void follow_path(const Scene& scene, const Rings* rings, Vec3 o, Vec3 d, RGB power, std::vector<VirtualLight>& out) {
    for (int reflection = 0; reflection <= kMaxRingReflections; ++reflection) {
        const RoomSurface room = room_surface(scene.environment, o, d);
        double t_room = std::isfinite(room.t) ? room.t : 1e30;
        const SphereHit sphere = nearest_sphere(scene.spheres, o, d);
        std::optional<RingHit> ring;
        if (rings) ring = intersect_rings(rings->rings, o, d, 1e-9, t_room);
        if (sphere.sphere >= 0 && sphere.t < t_room && (!ring || sphere.t < ring->t)) return;  // a metal sphere
        if (ring) {
            const RGB f = (*rings->fresnel.at(ring->ring))(std::clamp(-dot(d, ring->normal), 0.0, 1.0));
            power = times(power, f);
            o = ring->point;
            d = reflect(d, ring->normal);
            continue;
        }
        if (!room.diffuse || t_room >= 1e30) return;  // an emitter (a ceiling panel) or nothing
        out.push_back({room.point, room.normal, (1.0 / kPi) * times(power, room.albedo)});
        return;
    }
}

}  // namespace

std::vector<VirtualLight> shoot_virtual_lights(const Scene& scene, const IndirectSettings& settings) {
    std::vector<VirtualLight> out;
    const Lights* lights = scene.effects.find<Lights>();
    if (!lights || scene.environment.type != EnvironmentType::room) return out;
    const Rings* rings = scene.effects.find<Rings>();
    if (rings && rings->rings.empty()) rings = nullptr;
    const Room& room = scene.environment.room;
    const int n = settings.paths;
    for (const Light& light : lights->lights) {
        if (light.type == LightType::sphere) continue;  // not shot (docs/preview.md)
        if (light.local()) {
            // A Fibonacci spiral of directions over the light's cap (a point light's: the whole sphere; a spot's: its
            // outer cone), even in solid angle: n paths of I · the cap's solid angle / n each (a spot's times its cone
            // weight).
            const bool spot = light.type == LightType::spot;
            const double cap_cos = spot ? std::cos(light.cone_outer_deg * kPi / 180) : -1.0;
            const Vec3 w = spot ? light.direction : Vec3{0, 1, 0};
            const Vec3 a = normalize(std::abs(w.y) < 0.99 ? cross(w, Vec3{0, 1, 0}) : cross(w, Vec3{1, 0, 0}));
            const Vec3 b = cross(w, a);
            const double solid_angle = 2 * kPi * (1 - cap_cos);
            for (int k = 0; k < n; ++k) {
                const double z = 1 - (1 - cap_cos) * (k + 0.5) / n, r = std::sqrt(std::max(0.0, 1 - z * z));
                const double phi = k * kPi * (3 - std::sqrt(5.0));
                const Vec3 d = normalize(z * w + r * std::cos(phi) * a + r * std::sin(phi) * b);
                const double cone = spot ? spot_weight(light, dot(d, light.direction)) : 1.0;
                if (cone <= 0) continue;
                follow_path(scene, rings, light.position, d, (solid_angle / n * cone) * light.power(), out);
            }
            continue;
        }
        // A directional light: a square grid over its shadow plane (which covers the room), E × the cell's area
        // each, entering the room where the ray crosses its box (the walls let directional light through).
        const ShadowPlane plane = shadow_plane(room, light);
        const int side = std::max(1, static_cast<int>(std::lround(std::sqrt(static_cast<double>(n)))));
        const double cell = length(cross(plane.axis_u, plane.axis_v)) / (side * side);
        for (int i = 0; i < side; ++i)
            for (int j = 0; j < side; ++j) {
                const Vec3 o = plane.origin + ((i + 0.5) / side) * plane.axis_u + ((j + 0.5) / side) * plane.axis_v;
                const Vec3 d = plane.direction;
                double t_enter = -1e30, t_exit = 1e30;
                for (int a = 0; a < 3; ++a) {
                    const double inv = 1.0 / (std::abs(d[a]) < 1e-12 ? (d[a] < 0 ? -1e-12 : 1e-12) : d[a]);
                    const double t1 = (room.min[a] - o[a]) * inv, t2 = (room.max[a] - o[a]) * inv;
                    t_enter = std::max(t_enter, std::min(t1, t2));
                    t_exit = std::min(t_exit, std::max(t1, t2));
                }
                if (t_enter >= t_exit) continue;
                follow_path(scene, rings, o + (t_enter + 1e-6) * d, d, cell * light.power(), out);
            }
    }
    return out;
}

double evaluation_cutoff(std::span<const double> potentials, double rate) {
    double total = 0, largest = 0;
    for (const double w : potentials)
        if (w > 0) {
            total += w;
            largest = std::max(largest, w);
        }
    double lo = 0, hi = largest;  // S(lo) ≥ rate·total always; the answer lies in [lo, hi]
    for (int step = 0; step < 24; ++step) {
        const double c = 0.5 * (lo + hi);
        double held = 0;
        for (const double w : potentials)
            if (w >= c) held += w;
        (held >= rate * total ? lo : hi) = c;
    }
    return lo;
}

bool segment_blocked(const Scene& scene, Vec3 p, Vec3 q) {
    const Vec3 v = q - p;
    const double distance = length(v);
    if (!(distance > 1e-9)) return false;
    const Vec3 d = (1.0 / distance) * v;
    if (occluded(scene, p, d, distance - 1e-4)) return true;
    if (const Rings* rings = scene.effects.find<Rings>())
        if (intersect_rings(rings->rings, p, d, 1e-6, distance - 1e-4)) return true;
    return false;
}

IndirectGather gather_virtual_lights(const Scene& scene, std::span<const VirtualLight> lights,
                                     const IndirectSettings& settings, const RGB& albedo, Vec3 p, Vec3 n,
                                     bool priority) {
    IndirectGather g;
    const double clamp2 = settings.clamp_distance * settings.clamp_distance;
    std::vector<RGB> potential(lights.size(), RGB{0, 0, 0});
    std::vector<double> weight(lights.size(), 0.0);
    double total = 0;
    for (std::size_t i = 0; i < lights.size(); ++i) {
        const Vec3 v = lights[i].position - p;
        const double d2 = dot(v, v);
        if (!(d2 > 0)) continue;
        const Vec3 dir = (1.0 / std::sqrt(d2)) * v;
        const double cos_x = dot(n, dir), cos_y = -dot(lights[i].normal, dir);
        if (cos_x <= 0 || cos_y <= 0) continue;
        potential[i] = (cos_x * cos_y / std::max(d2, clamp2)) * lights[i].intensity;
        weight[i] = (potential[i].r + potential[i].g + potential[i].b) / 3;
        total += weight[i];
        ++g.candidates;
    }
    if (!(total > 0)) return g;
    // The priority scheme: the largest potentials first, until they hold the evaluation rate of the total.
    double cutoff = 0;
    if (priority) {
        std::vector<double> sorted(weight);
        std::sort(sorted.begin(), sorted.end(), std::greater<>());
        double held = 0;
        for (const double w : sorted) {
            if (!(w > 0)) break;
            held += w;
            cutoff = w;
            if (held >= settings.evaluation_rate * total) break;
        }
    }
    RGB sum{0, 0, 0};
    double tested = 0;
    for (std::size_t i = 0; i < lights.size(); ++i) {
        if (!(weight[i] > 0)) continue;
        if (priority && weight[i] < cutoff) continue;
        tested += weight[i];
        ++g.shadow_rays;
        if (!segment_blocked(scene, p, lights[i].position)) sum = sum + potential[i];
    }
    const double scale = tested > 0 ? total / tested : 0;
    g.radiance = (scale / kPi) * times(albedo, sum);
    return g;
}

}  // namespace metalfit::glpreview
