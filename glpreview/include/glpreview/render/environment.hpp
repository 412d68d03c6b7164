// The environment on the CPU: exact ray casting of the analytic room / sphere room and bilinear lookups of the
// equirect image, written to match shaders/environment.glsl line by line (the GPU capture and background use that
// file; tests compare the two).
#pragma once

#include <limits>

#include "glpreview/io/image.hpp"
#include "glpreview/scene/scene.hpp"

namespace metalfit::glpreview {

struct EnvironmentHit {
    RGB radiance;
    double t = std::numeric_limits<double>::infinity();  // ray parameter of the hit (∞ for an image at infinity)
};

class EnvironmentTracer {
public:
    // `equirect` must be the loaded image when the environment is an equirect one (kept by reference).
    EnvironmentTracer(const Environment& environment, const Image* equirect = nullptr);

    // Radiance seen from `origin` along unit direction `dir`, and where it is.
    EnvironmentHit trace(Vec3 origin, Vec3 dir) const;

private:
    EnvironmentHit trace_room(Vec3 origin, Vec3 dir) const;
    EnvironmentHit trace_sphere_room(Vec3 origin, Vec3 dir) const;
    RGB equirect_radiance(Vec3 dir) const;

    const Environment& environment_;
    const Image* equirect_;
};

// Bilinear lookup in an equirect image (u wraps, v clamps), as the shader does it with texelFetch.
RGB sample_equirect(const Image& image, Vec3 dir);

}  // namespace metalfit::glpreview
