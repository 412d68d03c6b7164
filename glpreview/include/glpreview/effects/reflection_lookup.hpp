// The reflection effect's lookup as other code uses it: its part of a program, and a probe that runs the spheres'
// GLSL for given rays (tests, benchmarks). Implemented in src/effects/reflection/.
#pragma once

#include <array>
#include <span>
#include <vector>

#include "glpreview/render/shader_builder.hpp"
#include "glpreview/scene/scene.hpp"
#include "glpreview/scene/vec3.hpp"

namespace metalfit::glpreview {

class GpuRenderer;

// The lookup's part of a program for a sphere's reflection settings: its #defines, reflection.glsl and u_env.
void declare_reflection_lookup(const Sphere& sphere, ShaderBuilder& builder);

// One probed reflection: where the lookup went, and the cube texel (radiance, distance) found there.
struct ProbeResult {
    Vec3 lookup;                 // not normalised
    std::array<float, 4> texel;  // rgb radiance, a distance (when the cube stores distance)
    int distance_lookups = 0;    // the impostor's distance reads for this ray (D(R), the search, the refinement)
};
// Reflection lookups of a sphere's reflection settings for rays (x relative to the reference point, unit R),
// computed by the shader code the spheres use. Needs the renderer's captured cube map.
std::vector<ProbeResult> probe_reflection_lookups(GpuRenderer& renderer, const Sphere& settings,
                                                  std::span<const std::array<Vec3, 2>> rays);

}  // namespace metalfit::glpreview
