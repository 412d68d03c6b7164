// What effects add to the CPU references (Effect::cpu_*; the reference effect gathers them from the registry):
// light on the room's surfaces (through the EnvironmentTracer), emitters that camera and mirror rays see before the
// environment, and the direct light on a point of a rough sphere with its Monte-Carlo variance. Empty members: none.
#pragma once

#include <cstddef>
#include <cstdint>
#include <functional>
#include <optional>

#include "glpreview/render/environment.hpp"
#include "glpreview/scene/vec3.hpp"
#include "libfit/color/color.hpp"

namespace metalfit::glpreview {

struct SphereFresnel;

// A radiance estimate: its mean and the variance of that mean (0 where exact).
struct RadianceEstimate {
    RGB mean{0, 0, 0};
    RGB variance{0, 0, 0};
};

struct CpuLighting {
    SurfaceLight surface;
    // The objects effects stand in the room (the rings), which the environment tracer meets before the room.
    EnvironmentObjects objects;
    // The emitter a ray from `origin` along unit `dir` meets first, if any: its radiance.
    std::function<std::optional<RGB>(Vec3 origin, Vec3 dir)> emitter;
    // The direct light reflected towards unit `v` at point p (unit normal n) of sphere `sphere`, roughness > 0.
    std::function<RadianceEstimate(std::size_t sphere, Vec3 p, Vec3 n, Vec3 v, const SphereFresnel& fresnel,
                                   int samples, std::uint64_t seed)>
        sphere_light;
};

}  // namespace metalfit::glpreview
