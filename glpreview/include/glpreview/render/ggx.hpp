// The GGX (Trowbridge–Reitz) microfacet lobe of a rough sphere, α = roughness² (docs/scene.md): Smith's
// height-correlated shadowing and Heitz's sampling of the visible normals (Eric Heitz, "Sampling the GGX
// Distribution of Visible Normals", JCGT 2018). In a local frame whose z axis is the surface normal. The CPU
// Monte-Carlo reference and the DFG tables use it; shaders/glossy.glsl is the same lobe on the GPU.
#pragma once

#include "glpreview/scene/vec3.hpp"

namespace metalfit::glpreview::ggx {

inline double alpha(double roughness) { return roughness * roughness; }

// Smith's Λ of a unit direction w (local frame), and G1 = 1 / (1 + Λ).
double smith_lambda(Vec3 w, double alpha);
// The height-correlated masking-shadowing G2(v, l) = 1 / (1 + Λ(v) + Λ(l)).
double smith_g2(Vec3 v, Vec3 l, double alpha);
// The normal distribution D(m) (m·z > 0; 0 otherwise).
double distribution(Vec3 m, double alpha);

// A microfacet normal m sampled from the visible normals seen from v (v.z > 0) with uniforms u1, u2 in [0, 1).
// α = 0 gives m = z (the mirror).
Vec3 sample_visible_normal(Vec3 v, double alpha, double u1, double u2);

// One visible-normal sample: the reflected direction l = 2(v·m)m − v, cos θ_d = v·m (where the Fresnel is
// evaluated) and the estimator weight f_r cos θ_l / pdf without the Fresnel, G2(v, l) / G1(v) (0 when l is below
// the surface).
struct LobeSample {
    Vec3 l;
    double cos_d = 1;
    double weight = 0;
};
LobeSample sample_reflection(Vec3 v, double alpha, double u1, double u2);

// An orthonormal frame around the unit normal n: local (x, y, z) → world t·x + b·y + n·z.
struct Frame {
    Vec3 t, b, n;
    explicit Frame(Vec3 normal);
    Vec3 to_world(Vec3 local) const { return local.x * t + local.y * b + local.z * n; }
    Vec3 to_local(Vec3 world) const { return {dot(world, t), dot(world, b), dot(world, n)}; }
};

// The i-th of n points of the Hammersley set in [0, 1)² (radical inverse in base 2).
void hammersley(unsigned i, unsigned n, double& u1, double& u2);

}  // namespace metalfit::glpreview::ggx
