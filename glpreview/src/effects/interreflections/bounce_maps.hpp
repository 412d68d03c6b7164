// The per-sphere distance maps of inter-reflections (Umenhoffer, Patow and Szirmay-Kalos, "Robust Multiple Specular
// Reflections and Refractions", GPU Gems 3 ch. 17, 2007: distance maps holding colour, distance and normal, searched
// with the root finders of Szirmay-Kalos et al., "Approximate Ray-Tracing on the GPU with Distance Impostors",
// 2005): per mapped sphere, taken from its centre, a front layer holding what the sphere sees (the room and rough
// spheres as the radiance they send to the centre, mirror spheres as their distance, normal and index, so that a
// reflected ray reaching one reflects again there: bounce.glsl) and a back layer holding the room alone (where a
// ray that passes behind a sphere of the front layer goes on). A static scene makes them once.
#pragma once

#include <optional>
#include <span>
#include <vector>

#include "bounce_plan.hpp"
#include "glpreview/gl/objects.hpp"
#include "glpreview/render/gpu_renderer.hpp"
#include "glpreview/render/gpu_resources.hpp"
#include "glpreview/scene/camera.hpp"

namespace metalfit::glpreview {

// A rough sphere's own map: what it sees from its centre (the room and every other sphere with its own program,
// mirrors with their bounces), and that prefiltered for its lobe as the room's cube is.
struct RoughMap {
    EnvironmentCube radiance;  // rgb the radiance, a the distance (read by the lobe's localized lookup); mip-mapped
    PrefilteredCube prefiltered;
};

struct BounceMaps {
    // Cube-map array, RGBA32F: rgb the radiance seen from the centre, a: the distance to it; layer L is the front
    // layer of a sphere, L + layers its back layer (the room alone).
    gl::Texture radiance;
    // Cube-map array, RGBA32F, the front layers: xyz the normal of the sphere seen, w: j + 1 for mirror sphere j,
    // −(j + 1) for rough sphere j (its radiance is the front layer's), 0 for the room.
    gl::Texture hits;
    gl::Texture spheres;  // 2D, a column per sphere, RGBA32F: row 0 its centre, w its layer (−1: no map); row 1 radius
    int size = 0;         // texels per face edge
    int layers = 0;       // mapped spheres
    std::vector<int> layer_of;                   // by sphere: its layer, −1 for none
    std::vector<std::optional<RoughMap>> rough;  // by sphere: a rough sphere's own map, when the plan gives one
};

// The maps' edge: the environment's cube size, at most 256 (a mapped sphere's three layers: 6 · size² · 48 bytes).
int bounce_map_size(const Scene& scene);

// The plan's maps into `maps` (which stays where it is: the mirrors' maps are put on the renderer's blackboard while
// the rough spheres' maps are drawn, since those show the mirrors with their bounces). Needs the environment and
// what the spheres' programs read bound on the renderer.
void render_bounce_maps(GpuRenderer& renderer, const BouncePlan& plan, BounceMaps& maps);

// Every sphere's Fresnel in the renderer's frames now (its reference LUT or its model, as GpuRenderer::fresnel),
// one row each over μ ∈ [0, 1] in kBounceFresnelTexels columns, RGB32F, linear: what a bounce multiplies.
inline constexpr int kBounceFresnelTexels = 256;
gl::Texture bounce_fresnel_table(const GpuRenderer& renderer);

// The camera of cube face `face` (0..5: +X, −X, +Y, −Y, +Z, −Z) seen from `center`: a sphere draw with it fills the
// face's texels as the capture's cube_direction() orders them.
CameraBasis cube_face_view(Vec3 center, int face);

}  // namespace metalfit::glpreview
