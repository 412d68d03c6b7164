// Virtual light sources (Lazányi's thesis, ch. 6, after Keller's instant radiosity; docs/preview.md, "Indirect light:
// virtual light sources"): light paths shot from the scene's lights, reflected by the rings with their Fresnel, and
// stored where they first meet a diffuse room surface, each a point source whose radiant intensity along its
// surface's normal is Φ·albedo/π; and their gathering at a room point, with every sample's visibility or with the
// thesis's priority scheme, which traces shadow rays only for samples that can matter.
#pragma once

#include <span>
#include <vector>

#include "glpreview/scene/scene.hpp"
#include "indirect_settings.hpp"

namespace metalfit::glpreview {

struct VirtualLight {
    Vec3 position, normal;  // on a room surface; the normal points into the room
    RGB intensity;          // W/sr along the normal: the power that arrived × the surface's albedo / π
};

// The virtual lights of the scene's point, spot and directional lights (settings.paths paths each, stratified and
// deterministic). A path that meets a sphere or a ceiling panel ends there (spheres are metals: no diffuse lobe; their
// reflections are the caustics' business, not followed here); one that meets a ring reflects with the ring's Fresnel
// (resolved: resolve_effect_materials), at most 4 times.
std::vector<VirtualLight> shoot_virtual_lights(const Scene& scene, const IndirectSettings& settings);

// The light of the virtual lights a Lambertian room point p (inward normal n, albedo) reflects: each sample's potential
// contribution I·cos θ_y·cos θ_x / max(d², clamp²) (the thesis's eq. 6.1 with its distance clamp) times albedo/π, and
// its visibility (spheres, room boxes, rings). `priority`: the thesis's priority scheme (ch. 6.3.1) — shadow rays for
// the samples in the order of their potential contribution, largest first, until the tested ones hold
// `evaluation_rate` of the point's total (the evaluation rate); the sum is then scaled by the total over the tested
// samples' (the thesis's compensation for the ones left out).
// The cut-off potential that rule stops at, found without sorting (what the GPU does): the largest c such that the
// samples with potential ≥ c hold at least rate × total, by bisection on c.
double evaluation_cutoff(std::span<const double> potentials, double rate);
struct IndirectGather {
    RGB radiance{0, 0, 0};
    int candidates = 0;   // samples facing the point (a shadow ray each without the priority scheme)
    int shadow_rays = 0;  // shadow rays traced
};
IndirectGather gather_virtual_lights(const Scene& scene, std::span<const VirtualLight> lights,
                                     const IndirectSettings& settings, const RGB& albedo, Vec3 p, Vec3 n,
                                     bool priority);

// Whether the segment from p to q is blocked by a sphere, a room box or a ring.
bool segment_blocked(const Scene& scene, Vec3 p, Vec3 q);

}  // namespace metalfit::glpreview
