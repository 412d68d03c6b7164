// The grazing-rim unwrap (issue 36 item 1): for a sphere on the camera's axis the silhouette is a circle whose
// radius follows from the sphere's angular size, so where each pixel belongs in the unwrap, and the μ of the rim,
// can be computed here without the code under test.
#include <gtest/gtest.h>

#include <cmath>
#include <numbers>

#include "glpreview/render/rim_unwrap.hpp"
#include "glpreview/scene/camera.hpp"

namespace metalfit::glpreview {
namespace test_preview_rim {

constexpr int kWidth = 200, kHeight = 160;
constexpr double kFov = 45;  // the sphere at distance 3 fills 68 of the 80 rows above the centre

// A sphere of radius 1 at the origin, the camera at distance `d` on +z looking at it.
struct OnAxis {
    double d;
    Sphere sphere;
    CameraBasis camera;
    double silhouette_px;  // tan(asin(r / d)) / tan(fov / 2) × height / 2

    explicit OnAxis(double distance) : d(distance) {
        sphere.center = {0, 0, 0};
        sphere.radius = 1;
        Camera c;
        c.position = {0, 0, d};
        c.look_at = {0, 0, 0};
        c.fov_y_deg = kFov;
        camera = camera_basis(c, kWidth, kHeight);
        const double tan_half = std::tan(0.5 * kFov * std::numbers::pi / 180);
        silhouette_px = std::tan(std::asin(1 / d)) / tan_half * kHeight / 2;
    }
    // μ where the camera ray at angle θ off the axis meets the sphere: the centre is d sin θ from the ray.
    double mu_at_angle(double theta) const {
        const double p = d * std::sin(theta);
        return std::sqrt(1 - p * p);
    }
    // The angle off the axis of an image point `r` pixels from the image centre.
    double angle_of(double r) const {
        return std::atan(r / (kHeight / 2.0) * std::tan(0.5 * kFov * std::numbers::pi / 180));
    }
};

TEST(RimUnwrap, TheSilhouetteOfASphereOnTheAxisIsTheCircleOfItsAngularSize) {
    for (const double d : {3.0, 8.0}) {
        const OnAxis s(d);
        const RimGeometry rim(s.camera, s.sphere, kWidth, kHeight);
        ASSERT_TRUE(rim.visible());
        EXPECT_NEAR(rim.centre().x, kWidth / 2.0, 1e-9);
        EXPECT_NEAR(rim.centre().y, kHeight / 2.0, 1e-9);
        for (double phi = 0.1; phi < 6.3; phi += 0.7)
            EXPECT_NEAR(rim.silhouette_distance(phi), s.silhouette_px, 1e-6 * s.silhouette_px) << d << " " << phi;
    }
}

// A marker pixel at 0.95 of the silhouette and angle φ lands in the unwrap's column φ / 2π and the row of s = 0.95.
TEST(RimUnwrap, AMarkerAtRadius095AndAngleLandsInItsColumnAndRow) {
    const OnAxis s(3.0);
    const RimGeometry rim(s.camera, s.sphere, kWidth, kHeight);
    constexpr int columns = 720, rows = 40;
    const RimUnwrap unwrap = unwrap_rim(rim, kWidth, kHeight, columns, rows);
    for (const double phi : {0.3, 1.6, 2.9, 4.4, 5.9}) {
        // The pixel holding the point at 0.95 r, angle φ (counterclockwise from +x, y up on the screen).
        const double r = 0.95 * s.silhouette_px;
        const int x = static_cast<int>(std::floor(kWidth / 2.0 + r * std::cos(phi)));
        const int y = static_cast<int>(std::floor(kHeight / 2.0 - r * std::sin(phi)));
        Image image(kWidth, kHeight);
        image.set(x, y, {1, 1, 1});
        const Image strip = sample_rim(image, unwrap);
        // Its centre's own polar coordinates, computed here, and the cell they fall in.
        const double dx = x + 0.5 - kWidth / 2.0, dy = kHeight / 2.0 - (y + 0.5);
        double angle = std::atan2(dy, dx);
        if (angle < 0) angle += 2 * std::numbers::pi;
        const double fraction = std::hypot(dx, dy) / s.silhouette_px;
        const int column = static_cast<int>(angle / (2 * std::numbers::pi) * columns);
        const int row = static_cast<int>((1 - fraction) / (1 - kRimInner) * rows);
        SCOPED_TRACE("phi " + std::to_string(phi));
        ASSERT_TRUE(row >= 0 && row < rows);
        EXPECT_EQ(strip.at(column, row).g, 1.0f);
        // And nowhere far from there: every lit cell is within the pixel's extent (magnified) of that cell.
        int lit = 0;
        for (int j = 0; j < rows; ++j)
            for (int k = 0; k < columns; ++k)
                if (strip.at(k, j).g > 0) {
                    ++lit;
                    EXPECT_LE(std::abs(j - row), rows / (0.1 * s.silhouette_px) + 1) << k << " " << j;
                    const int dk = std::abs(k - column);
                    EXPECT_LE(std::min(dk, columns - dk), columns / (2 * std::numbers::pi * r) * 1.5 + 1);
                }
        EXPECT_GT(lit, 1) << "magnified: one pixel covers several cells";
    }
}

// μ at the rim's inner edge is that of the ray at 0.9 of the silhouette: sqrt(1 − 0.9²) seen from far away, the
// perspective value from up close; the rim's pixels span from near 0 up to it.
TEST(RimUnwrap, TheRimsMuRangeIsThatOfItsInnerEdge) {
    for (const double d : {3.0, 400.0}) {
        OnAxis s(d);
        Camera far;
        if (d > 100) {  // far away: narrow the view so that the sphere still fills the image
            far.position = {0, 0, d};
            far.look_at = {0, 0, 0};
            far.fov_y_deg = 2 * std::atan(std::tan(std::asin(1 / d)) / 0.8) * 180 / std::numbers::pi;
            s.camera = camera_basis(far, kWidth, kHeight);
            s.silhouette_px = 0.8 * kHeight / 2;
        }
        const RimGeometry rim(s.camera, s.sphere, kWidth, kHeight);
        const double tan_half = std::tan(0.5 * (d > 100 ? far.fov_y_deg : kFov) * std::numbers::pi / 180);
        const double inner_angle = std::atan(kRimInner * s.silhouette_px / (kHeight / 2.0) * tan_half);
        const double inner_mu = s.mu_at_angle(inner_angle);
        SCOPED_TRACE("d " + std::to_string(d));
        const auto mu = sphere_mu(s.camera, s.sphere, rim.at(1.0, kRimInner), kWidth, kHeight);
        ASSERT_TRUE(mu);
        EXPECT_NEAR(*mu, inner_mu, 1e-6);
        if (d > 100) {
            EXPECT_NEAR(inner_mu, std::sqrt(1 - kRimInner * kRimInner), 1e-4);
        }
        // The pixels of the sphere (the centre's distance from the ray below the radius), the rim among them.
        ReferenceRender reference{Image(kWidth, kHeight), std::vector<int>(kWidth * kHeight, -1)};
        for (int y = 0; y < kHeight; ++y)
            for (int x = 0; x < kWidth; ++x) {
                const double r = std::hypot(x + 0.5 - kWidth / 2.0, y + 0.5 - kHeight / 2.0);
                if (d * std::sin(std::atan(r / (kHeight / 2.0) * tan_half)) < 1)
                    reference.sphere_id[y * kWidth + x] = 0;
            }
        const MuRange range = rim_mu_range(rim, s.camera, s.sphere, reference, 0);
        EXPECT_GT(range.pixels, 100u);
        EXPECT_LE(range.max, inner_mu + 1e-12);
        EXPECT_GT(range.max, inner_mu - 0.03) << "a pixel centre lies close to the inner edge";
        EXPECT_LT(range.min, 0.15) << "and one close to the silhouette";
        EXPECT_EQ(rim_mu_range(rim, s.camera, s.sphere, reference, 1).pixels, 0u);
    }
}

}  // namespace test_preview_rim
}  // namespace metalfit::glpreview
