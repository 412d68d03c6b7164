// The scene's rings (docs/scene.md, "Rings"): concave metal reflectors standing in the room, each a section of a
// vertical cylinder's wall of zero thickness, a mirror on both sides (roughness 0) with a sphere's Fresnel choice
// (material, source, fresnel, params). A ring is drawn, reflected, captured and shadowed like the room's own
// geometry; the caustics effect throws its light onto the room. The intersection here is the one the GPU's
// ring.glsl repeats line by line, and the CPU references and the photon tracer call.
#pragma once

#include <optional>
#include <string>
#include <vector>

#include "glpreview/scene/scene.hpp"
#include "glpreview/scene/scene_reader.hpp"

namespace metalfit::glpreview {

struct SphereFresnel;

struct Ring {
    Vec3 base;              // the centre of the cylinder's bottom circle (on the floor when it stands there)
    double radius = 1;      // m
    double height = 0.3;    // m, upwards from base
    double arc_deg = 180;   // the wall's angular extent, (0, 360]
    double facing_deg = 0;  // azimuth of the arc's middle: the wall point base + radius (cos φ, 0, sin φ)
    std::string material = "Au";
    std::string source;
    FresnelChoice fresnel = ReferenceFresnel{};

    // Whether the wall includes the azimuth of horizontal offset (x, z) from the axis.
    bool covers(double x, double z) const;
    // The smallest sphere around the wall's cylinder: centred half-way up the axis, of radius √(R² + (h/2)²) (what
    // the shadow maps, the caustic maps and the photon tracer aim at).
    BoundingSphere bounds() const;
    // The ring as a sphere of the same material and Fresnel choice (what FresnelLibrary resolves).
    Sphere surface() const;
};

// The rings of a scene (Scene::effects) and, once the preview resolved them (resolve_rings), their Fresnel,
// fresnel[i] of rings[i].
struct Rings {
    std::vector<Ring> rings;
    std::vector<const SphereFresnel*> fresnel;
};
inline constexpr std::size_t kMaxRings = 4;  // the shaders' MAX_RINGS

// Where a ray meets a ring's wall: its parameter, the point, the unit normal facing the ray's origin (either side of
// the wall reflects) and whether that side is the inner, concave one.
struct RingHit {
    double t = 0;
    Vec3 point, normal;
    bool inner = false;
    std::size_t ring = 0;
};
// The first wall of `ring` the ray o + t d (d unit) meets with t_min < t < t_max.
std::optional<RingHit> intersect_ring(const Ring& ring, Vec3 o, Vec3 d, double t_min, double t_max);
// The first wall of any ring.
std::optional<RingHit> intersect_rings(const std::vector<Ring>& rings, Vec3 o, Vec3 d, double t_min, double t_max);

// The "rings" key (an array), read strictly: errors name the file and the field.
Rings read_rings(const SceneReader& top);
// The checks that need the room: a room environment and every ring inside it.
void check_rings(const SceneReader& top, const Scene& scene, const Rings& rings);

}  // namespace metalfit::glpreview
