// The grazing rim of a sphere in a rendered image, unwrapped (docs/preview.md, "Error views"): the pixels from
// kRimInner of the way out from the sphere's projected centre to its silhouette, laid out with the angle around the
// rim horizontally and the radial position vertically. Exact under the perspective camera (render/camera): the
// projected centre is the image of the sphere's centre, the silhouette distance at each angle is found by bisection
// on "the camera ray hits the sphere", and μ = N·V of a pixel is its camera ray's at the first hit. No GL.
#pragma once

#include <optional>
#include <vector>

#include "glpreview/render/cpu_reference.hpp"
#include "glpreview/scene/camera.hpp"

namespace metalfit::glpreview {

// The rim starts at this fraction s of the silhouette's distance from the projected centre (the outer 10 %). Seen
// from far away (orthographic), s and μ are tied by μ = sqrt(1 − s²): the rim holds μ ≤ sqrt(1 − 0.9²) ≈ 0.436.
inline constexpr double kRimInner = 0.9;

// A point of the image in continuous coordinates: x from the left edge, y from the top edge, in pixels (pixel (i, j)
// of the top-row-first image covers [i, i + 1) × [j, j + 1), its centre at (i + 0.5, j + 0.5)).
struct ImagePoint {
    double x = 0, y = 0;
};

// Where a point of the scene lands in a width × height image (nothing behind the camera).
std::optional<ImagePoint> project_point(const CameraBasis& camera, Vec3 p, int width, int height);
// The camera ray through a continuous image point (camera_ray at pixel centres).
Vec3 camera_ray_at(const CameraBasis& camera, ImagePoint at, int width, int height);
// μ = N·V where the ray through `at` first meets the sphere (nothing when it misses).
std::optional<double> sphere_mu(const CameraBasis& camera, const Sphere& sphere, ImagePoint at, int width, int height);

// One sphere's rim in the image: the projected centre and the silhouette's distance from it at each angle.
class RimGeometry {
public:
    RimGeometry(const CameraBasis& camera, const Sphere& sphere, int width, int height);
    bool visible() const { return visible_; }  // the centre projects in front of the camera
    ImagePoint centre() const { return centre_; }
    // φ counterclockwise on the screen from the image's +x axis (0: right, π/2: up).
    double silhouette_distance(double phi) const;
    // The image point at angle φ and fraction s of the silhouette distance.
    ImagePoint at(double phi, double s) const;
    // The fraction s and angle φ of an image point (φ in [0, 2π)).
    std::pair<double, double> polar(ImagePoint p) const;

private:
    CameraBasis camera_;
    Sphere sphere_;
    int width_, height_;
    bool visible_ = false;
    ImagePoint centre_;
};

// The unwrapped rim: `columns` angles φ_k = 2π (k + 0.5) / columns, `rows` fractions s_j = 1 − (1 − kRimInner)
// (j + 0.5) / rows (the silhouette at the top row, kRimInner at the bottom); each cell the image pixel its point
// falls in (nearest: the strip shows the image's own pixels, magnified), −1 outside the image.
struct RimUnwrap {
    int columns = 0, rows = 0;
    std::vector<int> pixel;  // rows × columns, top row first: y · width + x of the image, or −1
};
RimUnwrap unwrap_rim(const RimGeometry& rim, int width, int height, int columns, int rows);
// The cells of `image` (RGB) or of per-pixel `values` at the unwrap's pixels (black / 0 outside the image).
Image sample_rim(const Image& image, const RimUnwrap& unwrap);
std::vector<double> sample_rim(const std::vector<double>& values, const RimUnwrap& unwrap);

// The μ of the rim's pixels: those the reference sees as sphere `index` whose centres lie at s ≥ kRimInner.
struct MuRange {
    double min = 0, max = 0;
    std::size_t pixels = 0;
};
MuRange rim_mu_range(const RimGeometry& rim, const CameraBasis& camera, const Sphere& sphere,
                     const ReferenceRender& reference, int index);

}  // namespace metalfit::glpreview
