// The environment on the CPU: exact ray casting of the analytic room / sphere room and bilinear lookups of the
// equirect image (at infinity, or painted on its box or sphere proxy), written to match shaders/environment.glsl line by line (the GPU capture and background use that
// file; tests compare the two).
#pragma once

#include <functional>
#include <limits>
#include <optional>

#include "glpreview/io/image.hpp"
#include "glpreview/scene/scene.hpp"

namespace metalfit::glpreview {

struct EnvironmentHit {
    RGB radiance;
    double t = std::numeric_limits<double>::infinity();  // ray parameter of the hit (∞ for an image at infinity)
};

// The light an effect adds to a room surface of albedo `albedo` at p with inward normal n (its reflected radiance),
// as ENVIRONMENT_LIGHTING does in environment.glsl.
using SurfaceLight = std::function<RGB(const RGB& albedo, Vec3 p, Vec3 n)>;

class EnvironmentTracer;
// The objects effects stand in a room (ENVIRONMENT_OBJECT in environment.glsl: the rings): whether the ray from o
// along unit d meets one before t_max (the room's own hit), and then its radiance and ray parameter; `room` traces
// the room alone (EnvironmentTracer::room_trace), as the GPU's reflected rays read it.
using EnvironmentObjects =
    std::function<std::optional<EnvironmentHit>(Vec3 o, Vec3 d, double t_max, const EnvironmentTracer& room)>;

class EnvironmentTracer {
public:
    // `equirect` must be the loaded image when the environment is an equirect one (kept by reference). `light`: the
    // light effects add to the room's surfaces (none: the room's emission alone); its albedo is a surface's colour
    // clamped to 1; ceiling panels are emitters and take none.
    // `objects`: what effects stand in a room (none: the room alone).
    EnvironmentTracer(const Environment& environment, const Image* equirect = nullptr, SurfaceLight light = {},
                      EnvironmentObjects objects = {});

    // Radiance seen from `origin` along unit direction `dir`, and where it is: the room and the objects in it.
    EnvironmentHit trace(Vec3 origin, Vec3 dir) const;
    // The same without the objects (environment.glsl's room_trace).
    EnvironmentHit room_trace(Vec3 origin, Vec3 dir) const;

private:
    EnvironmentHit trace_room(Vec3 origin, Vec3 dir) const;
    EnvironmentHit trace_sphere_room(Vec3 origin, Vec3 dir) const;
    EnvironmentHit trace_proxy(Vec3 origin, Vec3 dir) const;  // an equirect on its proxy
    RGB equirect_radiance(Vec3 dir) const;
    RGB surface(const RGB& colour, Vec3 p, Vec3 n) const;  // a room surface's radiance: colour plus light_

    const Environment& environment_;
    const Image* equirect_;
    SurfaceLight light_;
    EnvironmentObjects objects_;
};

// Bilinear lookup in an equirect image (u wraps, v clamps), as the shader does it with texelFetch.
RGB sample_equirect(const Image& image, Vec3 dir);
// The unit direction of an equirect image's texel centre (x + ½, y + ½), the inverse of sample_equirect's mapping
// (docs/scene.md, "Exact rules": u = 0.5 + atan2(d.x, −d.z)/2π, v = acos(d.y)/π).
Vec3 equirect_direction(int x, int y, int width, int height);
// The environment seen from `point` as a width × height equirect image (each texel centre's ray traced exactly): a
// reflection probe of a procedural room, as an engine would capture one.
Image capture_equirect(const EnvironmentTracer& environment, Vec3 point, int width, int height);

}  // namespace metalfit::glpreview
