#include "ring.hpp"

#include <cmath>
#include <numbers>

#include "libfit/base/errors.hpp"

namespace metalfit::glpreview {

bool Ring::covers(double x, double z) const {
    if (arc_deg >= 360) return true;
    const double to_radians = std::numbers::pi / 180;
    // The angle between the offset and the arc's middle, by the cosine: no wrap-around to handle.
    const double middle_x = std::cos(facing_deg * to_radians), middle_z = std::sin(facing_deg * to_radians);
    const double r = std::hypot(x, z);
    if (!(r > 0)) return false;
    return (x * middle_x + z * middle_z) / r >= std::cos(0.5 * arc_deg * to_radians);
}

BoundingSphere Ring::bounds() const { return {base + Vec3{0, 0.5 * height, 0}, std::hypot(radius, 0.5 * height)}; }

Sphere Ring::surface() const {
    Sphere s;
    s.material = material;
    s.source = source;
    s.fresnel = fresnel;
    return s;
}

std::optional<RingHit> intersect_ring(const Ring& ring, Vec3 o, Vec3 d, double t_min, double t_max) {
    // The infinite cylinder (x − c_x)² + (z − c_z)² = r², in the horizontal plane: a t² + 2 b t + c = 0.
    const double ox = o.x - ring.base.x, oz = o.z - ring.base.z;
    const double a = d.x * d.x + d.z * d.z;
    if (!(a > 1e-18)) return std::nullopt;  // a vertical ray runs along the wall
    const double b = ox * d.x + oz * d.z;
    const double c = ox * ox + oz * oz - ring.radius * ring.radius;
    const double h = b * b - a * c;
    if (h < 0) return std::nullopt;
    const double root = std::sqrt(h);
    for (const double t : {(-b - root) / a, (-b + root) / a}) {
        if (!(t > t_min && t < t_max)) continue;
        const Vec3 p = o + t * d;
        if (p.y < ring.base.y || p.y > ring.base.y + ring.height) continue;
        const double px = p.x - ring.base.x, pz = p.z - ring.base.z;
        if (!ring.covers(px, pz)) continue;
        const Vec3 outward{px / ring.radius, 0, pz / ring.radius};
        const bool inner = dot(d, outward) > 0;  // leaving the cylinder: the ray sees the concave side
        return RingHit{t, p, inner ? -1.0 * outward : outward, inner, 0};
    }
    return std::nullopt;
}

std::optional<RingHit> intersect_rings(const std::vector<Ring>& rings, Vec3 o, Vec3 d, double t_min, double t_max) {
    std::optional<RingHit> best;
    for (std::size_t i = 0; i < rings.size(); ++i) {
        if (auto hit = intersect_ring(rings[i], o, d, t_min, best ? best->t : t_max)) {
            hit->ring = i;
            best = hit;
        }
    }
    return best;
}

Rings read_rings(const SceneReader& top) {
    Rings result;
    top.each("rings", [&](const nlohmann::json& v, const std::string& path) {
        if (result.rings.size() >= kMaxRings) top.fail("rings", "at most " + std::to_string(kMaxRings) + " rings");
        const SceneReader r(
            v, path, top.file(),
            {"base", "radius", "height", "arc_deg", "facing_deg", "material", "source", "fresnel", "params"});
        Ring ring;
        if (!r.has("base")) r.fail(r.field("base"), "missing (the centre of the ring's bottom circle)");
        r.read("base", ring.base);
        for (int i = 0; i < 3; ++i)
            if (std::abs(ring.base[i]) > kSceneBig) r.fail(r.field("base"), "coordinates must be in [-1e+06, 1e+06]");
        if (r.has("radius") && r.at("radius").is_number() && !(r.at("radius").get<double>() > 0))
            r.fail(r.field("radius"), "must be > 0");
        r.read("radius", ring.radius, 1e-4, kSceneBig);
        if (r.has("height") && r.at("height").is_number() && !(r.at("height").get<double>() > 0))
            r.fail(r.field("height"), "must be > 0");
        r.read("height", ring.height, 1e-4, kSceneBig);
        if (r.has("arc_deg") && r.at("arc_deg").is_number()) {
            const double arc = r.at("arc_deg").get<double>();
            if (!(arc > 0 && arc <= 360)) r.fail(r.field("arc_deg"), "must be in (0, 360]");
        }
        r.read("arc_deg", ring.arc_deg, 0, 360);
        r.read("facing_deg", ring.facing_deg, -360, 360);
        r.read("material", ring.material);
        r.read("source", ring.source);
        std::string fresnel = "reference", params = "fit";
        r.read("fresnel", fresnel);
        r.read("params", params);
        if (params != "fit" && params != "closed")
            r.fail(r.field("params"), "unknown value '" + scene_excerpt(params) + "' (known: fit, closed)");
        if (fresnel != "reference")
            ring.fresnel = ModelFresnel{fresnel, params == "closed" ? ParameterSource::closed : ParameterSource::fit};
        result.rings.push_back(ring);
    });
    return result;
}

void check_rings(const SceneReader& top, const Scene& scene, const Rings& rings) {
    if (rings.rings.empty()) return;
    if (scene.environment.type != EnvironmentType::room)
        top.fail("rings", "rings stand in a procedural room (environment type 'room')");
    const Room& room = scene.environment.room;
    for (std::size_t i = 0; i < rings.rings.size(); ++i) {
        const Ring& ring = rings.rings[i];
        const std::string field = "rings[" + std::to_string(i) + "]";
        const bool inside = ring.base.x - ring.radius > room.min.x && ring.base.x + ring.radius < room.max.x &&
                            ring.base.z - ring.radius > room.min.z && ring.base.z + ring.radius < room.max.z &&
                            ring.base.y >= room.min.y && ring.base.y + ring.height < room.max.y;
        if (!inside)
            top.fail(field, "the ring must lie inside the room (its cylinder between the walls, base to top "
                            "between floor and ceiling)");
    }
}

}  // namespace metalfit::glpreview
