#include "bounce_plan.hpp"

#include <algorithm>
#include <array>

#include "glpreview/effects/bounces.hpp"
#include "libfit/base/text.hpp"

namespace metalfit::glpreview {
namespace {

// Whether the segment p → q meets the box [lo, hi] (slab test).
bool segment_meets_box(Vec3 p, Vec3 q, Vec3 lo, Vec3 hi) {
    const std::array<double, 3> from{p.x, p.y, p.z}, to{q.x, q.y, q.z}, min{lo.x, lo.y, lo.z}, max{hi.x, hi.y, hi.z};
    double enter = 0, leave = 1;
    for (int axis = 0; axis < 3; ++axis) {
        if (min[axis] > max[axis]) return false;
        const double d = to[axis] - from[axis];
        if (d == 0) {
            if (from[axis] < min[axis] || from[axis] > max[axis]) return false;
            continue;
        }
        double t0 = (min[axis] - from[axis]) / d, t1 = (max[axis] - from[axis]) / d;
        if (t0 > t1) std::swap(t0, t1);
        enter = std::max(enter, t0);
        leave = std::min(leave, t1);
        if (enter > leave) return false;
    }
    return true;
}

}  // namespace

bool BouncePlan::maps(std::size_t sphere) const {
    return std::find(mapped.begin(), mapped.end(), sphere) != mapped.end();
}
bool BouncePlan::maps_rough(std::size_t sphere) const {
    return std::find(rough_mapped.begin(), rough_mapped.end(), sphere) != rough_mapped.end();
}

bool hidden_by_room(const Scene& scene, const Sphere& a, const Sphere& b) {
    if (scene.environment.type != EnvironmentType::room) return false;
    const double margin = std::max(a.radius, b.radius);
    const Vec3 shrink{margin, margin, margin};
    for (const RoomBox& box : scene.environment.room.boxes)
        if (segment_meets_box(a.center, b.center, box.min + shrink, box.max - shrink)) return true;
    return false;
}

BouncePlan plan_bounces(const Scene& scene) {
    BouncePlan plan;
    plan.max_bounces = max_bounces(scene);
    if (plan.max_bounces <= 1) {
        plan.reason = "max_bounces 1 (the default): spheres reflect the environment alone";
        return plan;
    }
    std::vector<std::string> seen, rough_seen;
    for (std::size_t i = 0; i < scene.spheres.size(); ++i) {
        const Sphere& sphere = scene.spheres[i];
        if (sphere.rough() && sphere.glossy != GlossyMethod::prefiltered) continue;
        std::vector<std::string> others;
        for (std::size_t j = 0; j < scene.spheres.size(); ++j)
            if (j != i && !hidden_by_room(scene, sphere, scene.spheres[j])) others.push_back(std::to_string(j));
        if (others.empty()) continue;
        (sphere.rough() ? plan.rough_mapped : plan.mapped).push_back(i);
        (sphere.rough() ? rough_seen : seen).push_back(std::to_string(i) + " sees " + join(others));
    }
    const std::string bounces = "max_bounces " + std::to_string(plan.max_bounces);
    if (!plan.active()) {
        plan.reason = bounces + ", but no sphere sees another sphere" +
                      std::string(scene.spheres.size() < 2 ? " (one sphere)" : "") +
                      ": spheres reflect the environment alone";
        return plan;
    }
    const int size = std::min(scene.environment.cube_size, 256);
    std::vector<std::string> parts;
    if (!plan.mapped.empty())
        parts.push_back("mirror sphere " + join(seen, "; ") + ": " + std::to_string(plan.mapped.size()) +
                        " distance map(s) " + std::to_string(size) + "² from the spheres' centres (radiance, " +
                        "distance, normal), made once; a reflected ray that meets a mirror in them reflects again, " +
                        "up to " + std::to_string(plan.max_bounces) + " reflections");
    if (!plan.rough_mapped.empty())
        parts.push_back("rough sphere " + join(rough_seen, "; ") + ": " + std::to_string(plan.rough_mapped.size()) +
                        " radiance map(s) " + std::to_string(size) +
                        "² from their centres, prefiltered for their lobes");
    plan.reason = bounces + ": " + join(parts, "; ");
    return plan;
}

}  // namespace metalfit::glpreview
