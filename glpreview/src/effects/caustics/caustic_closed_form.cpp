#include "caustic_closed_form.hpp"

#include <cmath>

namespace metalfit::glpreview {
namespace {

std::optional<CausticFocus> none(std::string* why, const std::string& reason) {
    if (why) *why = reason;
    return std::nullopt;
}

}  // namespace

std::optional<CausticFocus> caustic_focus(const Ring& ring, const Light& light, std::string* why, double tolerance) {
    const double r = ring.radius;
    if (light.type == LightType::directional) {
        const Vec3 d = light.direction;
        const double horizontal = std::hypot(d.x, d.z);
        if (!(d.y < 0) || !(horizontal > 1e-9)) return none(why, "the light does not fall obliquely");
        const Vec3 h{d.x / horizontal, 0, d.z / horizontal};
        const double tan_e = -d.y / horizontal;
        if (!ring.covers(h.x, h.z)) return none(why, "the arc does not hold the wall point facing the light");
        const double height = 0.5 * r * tan_e;
        if (height > ring.height) return none(why, "the ring is lower than (R/2) tan e");
        return CausticFocus{ring.base + 0.5 * r * h, height, "nephroid cusp (R/2)"};
    }
    if (light.type == LightType::point || light.type == LightType::spot) {
        const Vec3 offset{light.position.x - ring.base.x, 0, light.position.z - ring.base.z};
        const double distance = length(offset);
        if (std::abs(distance - r) > tolerance * r) return none(why, "the light is not on the ring's circle");
        const Vec3 h = (-1.0 / distance) * offset;  // from the light across the axis
        const double y_light = light.position.y - ring.base.y;
        if (!(y_light > 0)) return none(why, "the light is not above the base");
        if (!ring.covers(h.x, h.z)) return none(why, "the arc does not hold the wall point opposite the light");
        const double height = 0.25 * y_light;
        if (height > ring.height) return none(why, "the ring is lower than y_L / 4");
        return CausticFocus{ring.base + (r / 3) * h, height, "cardioid axial point (R/3)"};
    }
    return none(why, "sphere lights are not traced");
}

}  // namespace metalfit::glpreview
