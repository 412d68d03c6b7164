// Where a ring's floor caustic focuses, in closed form (docs/preview.md, "Caustics: the reference and the per-model
// table"). The ring's normal is horizontal, so a reflected ray's horizontal part reflects as in the circle's plane and
// its vertical part is kept: the floor caustic is the plane caustic of the circle, each ray landing where its height
// runs out.
// - A directional light of horizontal direction ĥ and elevation e (tan e = −d_y / |d_h|): parallel rays reflected
//   near the wall point facing the light (base + R ĥ, normal −ĥ) focus paraxially at R/2 from the wall, the
//   nephroid's cusp base + (R/2) ĥ; the ray that lands there travelled R/2 horizontally and so dropped (R/2) tan e:
//   it left the wall at that height, which the ring must reach.
// - A point light on the circle (horizontally R from the axis, at azimuth −ĥ) at height y_L above the base: the ray
//   to the opposite wall point (2R away horizontally, object distance 2R for a mirror of focal length R/2) focuses at
//   s' = 1 / (2/R − 1/(2R)) = 2R/3 from that wall, the cardioid's axial point base + (R/3) ĥ; it falls y_L over the
//   whole horizontal path 2R + 2R/3 = 8R/3 and so meets the wall at y_L (1 − 2R / (8R/3)) = y_L / 4.
#pragma once

#include <optional>
#include <string>

#include "../lights/light.hpp"
#include "../rings/ring.hpp"

namespace metalfit::glpreview {

struct CausticFocus {
    Vec3 point;              // on the plane of the ring's base
    double wall_height = 0;  // above the base, where the ray landing there leaves the wall
    std::string form;        // "nephroid cusp (R/2)", "cardioid axial point (R/3)"
};

// The focus of `light` on the floor through `ring`, or none with the reason in `why`: a sphere light, a light that
// does not point down, a wall too low or an arc that does not hold the wall point, a point light off the circle
// (further than `tolerance` × R from it).
std::optional<CausticFocus> caustic_focus(const Ring& ring, const Light& light, std::string* why = nullptr,
                                          double tolerance = 1e-3);

}  // namespace metalfit::glpreview
