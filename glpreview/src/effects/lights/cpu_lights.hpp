// The lights on the CPU, for the references: exact shadow rays against every sphere and room box, sphere lights
// integrated over the solid angle they subtend (the room: a fixed 64-point spiral over the cone; the rough spheres'
// highlights: Monte Carlo with `samples` directions, with the variance of the mean).
#pragma once

#include <cstdint>
#include <optional>

#include "glpreview/render/cpu_lighting.hpp"
#include "glpreview/render/sphere_fresnel.hpp"
#include "light.hpp"

namespace metalfit::glpreview {

// Radiance a Lambertian room surface of `albedo` at p (inward normal n) reflects of the lights.
RGB light_on_surface(const Scene& scene, const Lights& lights, const RGB& albedo, Vec3 p, Vec3 n);
// The nearest sphere light a ray meets: its radiance.
std::optional<RGB> emitter_seen(const Lights& lights, Vec3 origin, Vec3 dir);
// The lights' direct specular at point p of rough sphere `sphere` towards v: exact for point, spot and directional
// lights; sphere lights by Monte Carlo over their cone (`samples` directions, seeded by `seed`).
RadianceEstimate specular_from_lights(const Scene& scene, const Lights& lights, std::size_t sphere, Vec3 p, Vec3 n,
                                      Vec3 v, const SphereFresnel& fresnel, int samples, std::uint64_t seed);
// Whether the segment from o along unit d up to t_max meets a sphere (but `skip`), a room box or an object an effect
// stands in the room (Effect::cpu_occluder: the rings).
bool occluded(const Scene& scene, Vec3 o, Vec3 d, double t_max, std::optional<std::size_t> skip = std::nullopt);
// The same with the spheres and boxes alone (the photon tracer meets the rings itself).
bool occluded_by_spheres_and_boxes(const Scene& scene, Vec3 o, Vec3 d, double t_max,
                                   std::optional<std::size_t> skip = std::nullopt);
// A spot's cone weight at cos_angle, as GLSL's smoothstep(cos outer, cos inner, cos_angle) in lights.glsl.
double spot_weight(const Light& light, double cos_angle);

}  // namespace metalfit::glpreview
