#include "light.hpp"

#include <algorithm>
#include <cmath>
#include <numbers>

#include "glpreview/effects/registry.hpp"

namespace metalfit::glpreview {

const char* intensity_unit(LightType type) {
    switch (type) {
        case LightType::point:
        case LightType::spot: return "W/sr";
        case LightType::directional: return "W/m2";
        case LightType::sphere: return "W/m2/sr";
    }
    return "";
}

Lights read_lights(const SceneReader& top) {
    Lights result;
    top.each("lights", [&](const nlohmann::json& v, const std::string& path) {
        if (result.lights.size() >= kMaxLights) top.fail("lights", "at most " + std::to_string(kMaxLights) + " lights");
        const SceneReader r(v, path, top.file(),
                            {"type", "position", "direction", "radius", "colour", "intensity", "unit", "cone_inner_deg",
                             "cone_outer_deg"});
        Light light;
        if (!r.has("type")) r.fail(r.field("type"), "missing (point, spot, directional or sphere)");
        r.read_enum("type", light.type, kLightTypeNames);
        const auto require = [&](const char* key) {
            if (!r.has(key))
                r.fail(r.field(key), std::string("missing (a ") + to_string(light.type) + " light needs it)");
        };
        const auto refuse = [&](const char* key) {
            if (r.has(key))
                r.fail(r.field(key), std::string("means nothing for a ") + to_string(light.type) + " light");
        };
        if (light.local()) {
            require("position");
            r.read("position", light.position);
            for (int i = 0; i < 3; ++i)
                if (std::abs(light.position[i]) > kSceneBig)
                    r.fail(r.field("position"), "coordinates must be in [-1e+06, 1e+06]");
        } else {
            refuse("position");
        }
        if (light.type == LightType::spot || light.type == LightType::directional) {
            require("direction");
            r.read("direction", light.direction);
            const double length_of = length(light.direction);
            if (!(length_of > 1e-12) || !std::isfinite(length_of))
                r.fail(r.field("direction"), "must be a non-zero vector");
            light.direction = (1.0 / length_of) * light.direction;
        } else {
            refuse("direction");
        }
        if (light.type == LightType::sphere) {
            require("radius");
            r.read("radius", light.radius, 1e-4, kSceneBig);
        } else {
            refuse("radius");
        }
        if (light.type == LightType::spot) {
            r.read("cone_inner_deg", light.cone_inner_deg, 0, 90);
            r.read("cone_outer_deg", light.cone_outer_deg, 0, 90);
            if (!(light.cone_outer_deg > 0)) r.fail(r.field("cone_outer_deg"), "must be in (0, 90]");
            if (light.cone_inner_deg > light.cone_outer_deg)
                r.fail(r.field("cone_inner_deg"), "must not exceed cone_outer_deg");
        } else {
            refuse("cone_inner_deg");
            refuse("cone_outer_deg");
        }
        r.read_color("colour", light.colour);
        require("intensity");
        r.read("intensity", light.intensity, 0, kSceneBig);
        if (r.has("unit")) {
            std::string unit;
            r.read("unit", unit);
            if (unit != intensity_unit(light.type))
                r.fail(r.field("unit"), "'" + scene_excerpt(unit) + "': a " + to_string(light.type) +
                                            " light's intensity is in " + intensity_unit(light.type));
        }
        result.lights.push_back(light);
    });
    return result;
}

void check_lights(const SceneReader& top, const Scene& scene, const Lights& lights) {
    if (lights.lights.empty()) return;
    if (scene.environment.type != EnvironmentType::room)
        top.fail("lights", "lights need a room environment (its surfaces receive the light)");
    const Room& room = scene.environment.room;
    for (std::size_t i = 0; i < lights.lights.size(); ++i) {
        const Light& light = lights.lights[i];
        if (!light.local()) continue;
        const std::string field = "lights[" + std::to_string(i) + "].position";
        for (int a = 0; a < 3; ++a)
            if (!(light.position[a] - light.radius > room.min[a] && light.position[a] + light.radius < room.max[a]))
                top.fail(field, light.radius > 0 ? "the light's sphere must lie inside the room" : "outside the room");
        for (std::size_t s = 0; s < scene.spheres.size(); ++s) {
            const Sphere& sphere = scene.spheres[s];
            if (length(light.position - sphere.center) < sphere.radius + light.radius)
                top.fail(field, light.radius > 0 ? "the light's sphere meets sphere " + std::to_string(s)
                                                 : "inside sphere " + std::to_string(s));
        }
        for (std::size_t b = 0; b < room.boxes.size(); ++b) {
            const RoomBox& box = room.boxes[b];
            bool inside = true;
            for (int a = 0; a < 3; ++a)
                inside = inside && light.position[a] > box.min[a] - light.radius &&
                         light.position[a] < box.max[a] + light.radius;
            if (inside) top.fail(field, "inside (or touching) room box " + std::to_string(b));
        }
    }
}

namespace {

// Whether a sphere of `centre` and `radius` can lie in the cone of a spot (axis, outer angle) seen from its apex.
bool in_cone(const Light& spot, Vec3 centre, double radius) {
    const Vec3 to = centre - spot.position;
    const double d = length(to);
    if (d <= radius) return true;
    const double angle = std::acos(std::clamp(dot(to, spot.direction) / d, -1.0, 1.0));
    return angle <= spot.cone_outer_deg * std::numbers::pi / 180 + std::asin(std::min(1.0, radius / d));
}

}  // namespace

ShadowLayout shadow_layout(const Scene& scene, const Lights& lights) {
    ShadowLayout layout;
    const Room& room = scene.environment.room;
    std::vector<BoundingSphere> casters;  // what the effects add to the room (rings)
    for (const Effect* effect : all_effects())
        for (const BoundingSphere& b : effect->shadow_casters(scene)) casters.push_back(b);
    const std::size_t occluders = scene.spheres.size() + room.boxes.size() + casters.size();
    for (const Light& light : lights.lights) {
        bool casts = occluders > 0;
        const std::string objects = casters.empty() ? "sphere or room box" : "sphere, ring or room box";
        std::string why = casts ? "" : "no " + objects + " casts a shadow";
        if (casts && light.type == LightType::spot) {
            casts = false;
            for (const Sphere& s : scene.spheres) casts = casts || in_cone(light, s.center, s.radius);
            for (const RoomBox& b : room.boxes)
                casts = casts || in_cone(light, 0.5 * (b.min + b.max), 0.5 * length(b.max - b.min));
            for (const BoundingSphere& b : casters) casts = casts || in_cone(light, b.centre, b.radius);
            if (!casts) why = "no " + objects + " lies in its cone";
        }
        if (!casts) {
            layout.layer.push_back(-1);
        } else if (light.local()) {
            layout.layer.push_back(layout.cubes++);
            why = "a " + std::to_string(kShadowMapSize) + "² distance cube map around it";
        } else {
            layout.layer.push_back(layout.planes++);
            why = "a " + std::to_string(kShadowMapSize) + "² distance plane across the room";
        }
        layout.why.push_back(why);
    }
    return layout;
}

ShadowPlane shadow_plane(const Room& room, const Light& light) {
    const Vec3 d = light.direction;
    const Vec3 helper = std::abs(d.y) < 0.99 ? Vec3{0, 1, 0} : Vec3{1, 0, 0};
    const Vec3 u = normalize(cross(helper, d)), v = cross(d, u);
    double u0 = 1e300, u1 = -1e300, v0 = 1e300, v1 = -1e300, w0 = 1e300;
    for (int corner = 0; corner < 8; ++corner) {
        const Vec3 c{(corner & 1) ? room.max.x : room.min.x, (corner & 2) ? room.max.y : room.min.y,
                     (corner & 4) ? room.max.z : room.min.z};
        u0 = std::min(u0, dot(c, u));
        u1 = std::max(u1, dot(c, u));
        v0 = std::min(v0, dot(c, v));
        v1 = std::max(v1, dot(c, v));
        w0 = std::min(w0, dot(c, d));
    }
    return {u0 * u + v0 * v + w0 * d, (u1 - u0) * u, (v1 - v0) * v, d};
}

}  // namespace metalfit::glpreview
