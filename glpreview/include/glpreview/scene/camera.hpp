// The pinhole camera: one ray through each pixel centre, the same on the CPU and in shaders/camera.glsl.
#pragma once

#include "glpreview/scene/scene.hpp"

namespace metalfit::glpreview {

struct CameraBasis {
    Vec3 position;
    Vec3 forward;  // unit
    Vec3 right;    // unit × tan(fov/2) × aspect
    Vec3 up;       // unit × tan(fov/2)
};

CameraBasis camera_basis(const Camera& camera, int width, int height);

// Unit direction through pixel (px, py), py counted from the bottom row (OpenGL's gl_FragCoord convention).
Vec3 camera_ray(const CameraBasis& basis, int px, int py, int width, int height);

}  // namespace metalfit::glpreview
