#include "glpreview/render/rim_unwrap.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <numbers>

namespace metalfit::glpreview {
namespace {

// The nearest hit of the ray o + t d (d unit) with the sphere, t > 0.
std::optional<double> hit_distance(Vec3 o, Vec3 d, const Sphere& sphere) {
    const Vec3 oc = o - sphere.center;
    const double b = dot(oc, d), c = dot(oc, oc) - sphere.radius * sphere.radius;
    const double disc = b * b - c;
    if (disc < 0) return std::nullopt;
    const double t = -b - std::sqrt(disc);
    if (t <= 0) return std::nullopt;
    return t;
}

}  // namespace

std::optional<ImagePoint> project_point(const CameraBasis& camera, Vec3 p, int width, int height) {
    const Vec3 d = p - camera.position;
    const double forward = dot(d, camera.forward);
    if (forward <= 0) return std::nullopt;
    const double ndc_x = dot(d, camera.right) / (dot(camera.right, camera.right) * forward);
    const double ndc_y = dot(d, camera.up) / (dot(camera.up, camera.up) * forward);
    return ImagePoint{0.5 * (ndc_x + 1.0) * width, 0.5 * (1.0 - ndc_y) * height};
}

Vec3 camera_ray_at(const CameraBasis& camera, ImagePoint at, int width, int height) {
    const double ndc_x = 2.0 * at.x / width - 1.0, ndc_y = 1.0 - 2.0 * at.y / height;
    return normalize(camera.forward + ndc_x * camera.right + ndc_y * camera.up);
}

std::optional<double> sphere_mu(const CameraBasis& camera, const Sphere& sphere, ImagePoint at, int width, int height) {
    const Vec3 d = camera_ray_at(camera, at, width, height);
    const auto t = hit_distance(camera.position, d, sphere);
    if (!t) return std::nullopt;
    const Vec3 n = (1.0 / sphere.radius) * (camera.position + *t * d - sphere.center);
    return std::clamp(-dot(n, d), 0.0, 1.0);
}

RimGeometry::RimGeometry(const CameraBasis& camera, const Sphere& sphere, int width, int height)
    : camera_(camera), sphere_(sphere), width_(width), height_(height) {
    const auto c = project_point(camera, sphere.center, width, height);
    visible_ = c.has_value() && hit_distance(camera.position, camera_ray_at(camera, *c, width, height), sphere);
    if (c) centre_ = *c;
}

ImagePoint RimGeometry::at(double phi, double s) const {
    const double r = s * silhouette_distance(phi);
    return {centre_.x + r * std::cos(phi), centre_.y - r * std::sin(phi)};
}

double RimGeometry::silhouette_distance(double phi) const {
    if (!visible_) return 0;
    const auto hits = [&](double r) {
        const ImagePoint p{centre_.x + r * std::cos(phi), centre_.y - r * std::sin(phi)};
        return hit_distance(camera_.position, camera_ray_at(camera_, p, width_, height_), sphere_).has_value();
    };
    // The projected centre is inside the sphere's image, which is convex: one crossing along each direction.
    double inside = 0, outside = 1;
    while (hits(outside) && outside < 1e7) outside *= 2;
    for (int i = 0; i < 60; ++i) {
        const double mid = 0.5 * (inside + outside);
        (hits(mid) ? inside : outside) = mid;
    }
    return 0.5 * (inside + outside);
}

std::pair<double, double> RimGeometry::polar(ImagePoint p) const {
    const double dx = p.x - centre_.x, dy = centre_.y - p.y;
    double phi = std::atan2(dy, dx);
    if (phi < 0) phi += 2 * std::numbers::pi;
    const double r = std::hypot(dx, dy), silhouette = silhouette_distance(phi);
    return {silhouette > 0 ? r / silhouette : std::numeric_limits<double>::infinity(), phi};
}

RimUnwrap unwrap_rim(const RimGeometry& rim, int width, int height, int columns, int rows) {
    RimUnwrap u{columns, rows, std::vector<int>(static_cast<std::size_t>(columns) * rows, -1)};
    if (!rim.visible()) return u;
    for (int k = 0; k < columns; ++k) {
        const double phi = 2 * std::numbers::pi * (k + 0.5) / columns;
        for (int j = 0; j < rows; ++j) {
            const double s = 1.0 - (1.0 - kRimInner) * (j + 0.5) / rows;
            const ImagePoint p = rim.at(phi, s);
            const int x = static_cast<int>(std::floor(p.x)), y = static_cast<int>(std::floor(p.y));
            if (x >= 0 && y >= 0 && x < width && y < height)
                u.pixel[static_cast<std::size_t>(j) * columns + k] = y * width + x;
        }
    }
    return u;
}

Image sample_rim(const Image& image, const RimUnwrap& unwrap) {
    Image out(unwrap.columns, unwrap.rows);
    for (std::size_t c = 0; c < unwrap.pixel.size(); ++c)
        if (const int p = unwrap.pixel[c]; p >= 0)
            for (int ch = 0; ch < 3; ++ch) out.rgb[3 * c + ch] = image.rgb[3 * static_cast<std::size_t>(p) + ch];
    return out;
}

std::vector<double> sample_rim(const std::vector<double>& values, const RimUnwrap& unwrap) {
    std::vector<double> out(unwrap.pixel.size(), 0.0);
    for (std::size_t c = 0; c < unwrap.pixel.size(); ++c)
        if (const int p = unwrap.pixel[c]; p >= 0) out[c] = values[static_cast<std::size_t>(p)];
    return out;
}

MuRange rim_mu_range(const RimGeometry& rim, const CameraBasis& camera, const Sphere& sphere,
                     const ReferenceRender& reference, int index) {
    MuRange range{std::numeric_limits<double>::infinity(), -std::numeric_limits<double>::infinity(), 0};
    const int width = reference.image.width, height = reference.image.height;
    for (int y = 0; y < height; ++y)
        for (int x = 0; x < width; ++x) {
            if (reference.sphere_id[static_cast<std::size_t>(y) * width + x] != index) continue;
            const ImagePoint p{x + 0.5, y + 0.5};
            if (rim.polar(p).first < kRimInner) continue;
            const auto mu = sphere_mu(camera, sphere, p, width, height);
            if (!mu) continue;
            range.min = std::min(range.min, *mu);
            range.max = std::max(range.max, *mu);
            ++range.pixels;
        }
    if (range.pixels == 0) range.min = range.max = std::nan("");
    return range;
}

}  // namespace metalfit::glpreview
