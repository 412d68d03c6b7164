#include "glpreview/scene/camera.hpp"

#include <cmath>
#include <numbers>

namespace metalfit::glpreview {

CameraBasis camera_basis(const Camera& camera, int width, int height) {
    const Vec3 forward = normalize(camera.look_at - camera.position);
    const Vec3 right = normalize(cross(forward, camera.up));
    const Vec3 up = cross(right, forward);
    const double tan_half = std::tan(0.5 * camera.fov_y_deg * std::numbers::pi / 180.0);
    const double aspect = static_cast<double>(width) / height;
    return {camera.position, forward, (tan_half * aspect) * right, tan_half * up};
}

Vec3 camera_ray(const CameraBasis& basis, int px, int py, int width, int height) {
    const double ndc_x = 2.0 * (px + 0.5) / width - 1.0;
    const double ndc_y = 2.0 * (py + 0.5) / height - 1.0;
    return normalize(basis.forward + ndc_x * basis.right + ndc_y * basis.up);
}

}  // namespace metalfit::glpreview
