#include "glpreview/render/environment.hpp"

#include <algorithm>
#include <cmath>
#include <numbers>
#include <stdexcept>

namespace metalfit::glpreview {
namespace {

// Direction components this close to 0 are replaced by ±1e-12 (a sign-keeping stand-in), as in the shader.
double safe(double d) { return std::abs(d) < 1e-12 ? (d < 0 ? -1e-12 : 1e-12) : d; }

bool checker_even(double a, double b, double size) {
    return ((static_cast<int>(std::floor(a / size)) + static_cast<int>(std::floor(b / size))) & 1) == 0;
}

}  // namespace

EnvironmentTracer::EnvironmentTracer(const Environment& environment, const Image* equirect, SurfaceLight light,
                                     EnvironmentObjects objects)
    : environment_(environment), equirect_(equirect), light_(std::move(light)), objects_(std::move(objects)) {
    if (environment.type == EnvironmentType::equirect && !equirect)
        throw std::invalid_argument("EnvironmentTracer: the equirect image is missing");
}

EnvironmentHit EnvironmentTracer::trace(Vec3 origin, Vec3 dir) const {
    const EnvironmentHit room = room_trace(origin, dir);
    if (!objects_ || environment_.type != EnvironmentType::room) return room;
    if (std::optional<EnvironmentHit> seen = objects_(origin, dir, room.t, *this)) return *seen;
    return room;
}

EnvironmentHit EnvironmentTracer::room_trace(Vec3 origin, Vec3 dir) const {
    switch (environment_.type) {
        case EnvironmentType::room: return trace_room(origin, dir);
        case EnvironmentType::sphere_room: return trace_sphere_room(origin, dir);
        case EnvironmentType::equirect:
            if (environment_.equirect.proxy) return trace_proxy(origin, dir);
            return {equirect_radiance(dir)};
    }
    return {};
}

// The image painted on its proxy: where the ray leaves the proxy (box or sphere around the capture point o), the
// image is read in the direction from o to that point (environment.glsl, ENV_EQUIRECT_BOX / _SPHERE).
EnvironmentHit EnvironmentTracer::trace_proxy(Vec3 origin, Vec3 d) const {
    const Vec3 x = origin - environment_.reference();
    double t = 0;
    if (const auto* sphere = std::get_if<SphereProxy>(&*environment_.equirect.proxy)) {
        const double b = dot(x, d), c = dot(x, x) - sphere->radius * sphere->radius;
        t = -b + std::sqrt(std::max(b * b - c, 0.0));
    } else {
        const BoxProxy& box = std::get<BoxProxy>(*environment_.equirect.proxy);
        const Vec3 lo = box.min - environment_.reference(), hi = box.max - environment_.reference();
        t = std::numeric_limits<double>::infinity();
        for (int i = 0; i < 3; ++i) {
            const double inv = 1.0 / safe(d[i]);
            t = std::min(t, std::max((hi[i] - x[i]) * inv, (lo[i] - x[i]) * inv));
        }
    }
    return {equirect_radiance(normalize(x + t * d)), t};
}

EnvironmentHit EnvironmentTracer::trace_room(Vec3 o, Vec3 d) const {
    const Room& room = environment_.room;
    const Vec3 inv{1.0 / safe(d.x), 1.0 / safe(d.y), 1.0 / safe(d.z)};
    // Leaving the room: the nearest of the three walls ahead.
    double t_best = std::numeric_limits<double>::infinity();
    int axis = 0;
    for (int i = 0; i < 3; ++i) {
        const double t = ((inv[i] > 0 ? room.max[i] : room.min[i]) - o[i]) * inv[i];
        if (t < t_best) {
            t_best = t;
            axis = i;
        }
    }
    const bool positive_side = inv[axis] > 0;
    int box_hit = -1;
    int box_axis = 0;
    for (std::size_t b = 0; b < room.boxes.size(); ++b) {
        const RoomBox& box = room.boxes[b];
        double t_near = -std::numeric_limits<double>::infinity(), t_far = std::numeric_limits<double>::infinity();
        int near_axis = 0;
        for (int i = 0; i < 3; ++i) {
            const double t1 = (box.min[i] - o[i]) * inv[i], t2 = (box.max[i] - o[i]) * inv[i];
            const double lo = std::min(t1, t2), hi = std::max(t1, t2);
            if (lo > t_near) {
                t_near = lo;
                near_axis = i;
            }
            t_far = std::min(t_far, hi);
        }
        if (t_near <= t_far && t_near > 0 && t_near < t_best) {
            t_best = t_near;
            box_hit = static_cast<int>(b);
            box_axis = near_axis;
        }
    }
    const Vec3 p = o + t_best * d;
    if (box_hit >= 0) {
        const double shade = box_axis == 1 ? 1.0 : box_axis == 0 ? 0.7 : 0.85;
        Vec3 n;
        n[box_axis] = d[box_axis] > 0 ? -1.0 : 1.0;  // the face the ray entered
        return {surface(shade * room.boxes[static_cast<std::size_t>(box_hit)].color, p, n), t_best};
    }
    Vec3 n;
    n[axis] = positive_side ? -1.0 : 1.0;  // the wall's inward normal
    if (axis == 1) {
        if (!positive_side)
            return {surface(checker_even(p.x, p.z, room.checker) ? room.floor_light : room.floor_dark, p, n), t_best};
        for (const CeilingPanel& panel : room.panels)
            if (p.x >= panel.min_x && p.x <= panel.max_x && p.z >= panel.min_z && p.z <= panel.max_z)
                return {panel.radiance, t_best};  // emitters
        return {surface(room.ceiling, p, n), t_best};
    }
    if (axis == 0) {
        const double shade = checker_even(p.z, p.y, room.checker) ? 1.0 : 0.75;
        return {surface(shade * (positive_side ? room.wall_x_max : room.wall_x_min), p, n), t_best};
    }
    const double shade = checker_even(p.x, p.y, room.checker) ? 1.0 : 0.75;
    return {surface(shade * (positive_side ? room.wall_z_max : room.wall_z_min), p, n), t_best};
}

RGB EnvironmentTracer::surface(const RGB& colour, Vec3 p, Vec3 n) const {
    if (!light_) return colour;
    const RGB albedo{std::min(colour.r, 1.0), std::min(colour.g, 1.0), std::min(colour.b, 1.0)};
    return colour + light_(albedo, p, n);
}

EnvironmentHit EnvironmentTracer::trace_sphere_room(Vec3 origin, Vec3 d) const {
    const SphereRoom& sr = environment_.sphere_room;
    const Vec3 p = origin - environment_.reference();
    const double b = dot(p, d), c = dot(p, p) - sr.radius * sr.radius;
    const double t = -b + std::sqrt(std::max(b * b - c, 0.0));
    const Vec3 u = normalize(p + t * d);
    const double to_deg = 180.0 / std::numbers::pi;
    const double lat = std::asin(std::clamp(u.y, -1.0, 1.0)) * to_deg;
    const double lon = std::atan2(u.z, u.x) * to_deg;
    return {checker_even(lat, lon, sr.checker_deg) ? sr.light : sr.dark, t};
}

RGB EnvironmentTracer::equirect_radiance(Vec3 dir) const {
    return environment_.equirect.intensity * sample_equirect(*equirect_, dir);
}

RGB sample_equirect(const Image& image, Vec3 d) {
    const double u = 0.5 + std::atan2(d.x, -d.z) / (2 * std::numbers::pi);
    const double v = std::acos(std::clamp(d.y, -1.0, 1.0)) / std::numbers::pi;
    const double x = u * image.width - 0.5, y = v * image.height - 0.5;
    const double x0 = std::floor(x), y0 = std::floor(y);
    const double fx = x - x0, fy = y - y0;
    auto wrap = [&](int i) { return ((i % image.width) + image.width) % image.width; };
    auto clamp_row = [&](int j) { return std::clamp(j, 0, image.height - 1); };
    const int xa = wrap(static_cast<int>(x0)), xb = wrap(static_cast<int>(x0) + 1);
    const int ya = clamp_row(static_cast<int>(y0)), yb = clamp_row(static_cast<int>(y0) + 1);
    const RGB top = (1 - fx) * image.at(xa, ya) + fx * image.at(xb, ya);
    const RGB bottom = (1 - fx) * image.at(xa, yb) + fx * image.at(xb, yb);
    return (1 - fy) * top + fy * bottom;
}

Vec3 equirect_direction(int x, int y, int width, int height) {
    const double phi = ((x + 0.5) / width - 0.5) * 2 * std::numbers::pi, theta = (y + 0.5) / height * std::numbers::pi;
    return {std::sin(theta) * std::sin(phi), std::cos(theta), -std::sin(theta) * std::cos(phi)};
}

Image capture_equirect(const EnvironmentTracer& environment, Vec3 point, int width, int height) {
    Image image(width, height);
    for (int y = 0; y < height; ++y)
        for (int x = 0; x < width; ++x)
            image.set(x, y, environment.trace(point, equirect_direction(x, y, width, height)).radiance);
    return image;
}

}  // namespace metalfit::glpreview
