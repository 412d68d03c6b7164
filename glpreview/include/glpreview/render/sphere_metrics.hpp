// Error of the GPU render against the CPU reference, per sphere: linear radiance inside the sphere's mask (the
// pixels where the reference sees that sphere), over the three channels.
#pragma once

#include <cstddef>
#include <vector>

#include "glpreview/io/image.hpp"
#include "glpreview/render/cpu_reference.hpp"

namespace metalfit::glpreview {

struct SphereError {
    double rmse = 0;      // sqrt(mean over mask pixels and channels of (beauty − reference)²)
    double mean_abs = 0;  // mean over mask pixels and channels of |beauty − reference|
    std::size_t pixels = 0;
};

std::vector<SphereError> sphere_errors(const Image& beauty, const ReferenceRender& reference, std::size_t spheres);

// The distance impostor's effort per sphere, from GpuRenderer::render_localization() over the same mask: the mean
// refinement steps taken and the mean and the largest |ρ − 1| at the lookup point (NaN where the mask is empty).
struct SphereLocalization {
    double mean_iterations = 0;
    double mean_rho_error = 0;
    double max_rho_error = 0;
};
std::vector<SphereLocalization> sphere_localization(const Image& diagnostics, const ReferenceRender& reference,
                                                    std::size_t spheres);

// The noise of a Monte-Carlo reference per sphere: sqrt(mean over the mask's pixels and channels of the standard
// error²), comparable to the RMSE (0 for mirror spheres, NaN where the mask is empty).
std::vector<double> sphere_reference_noise(const Image& standard_error, const ReferenceRender& reference,
                                           std::size_t spheres);

// The ΔE2000 of each sphere's mask (per pixel, from render/delta_e_view's delta_e_2000): the mean and the 95th
// percentile (linear interpolation between order statistics), NaN where the mask is empty.
struct SphereDeltaE {
    double mean = 0;
    double p95 = 0;
};
std::vector<SphereDeltaE> sphere_delta_e(const std::vector<double>& delta_e, const ReferenceRender& reference,
                                         std::size_t spheres);

// |a − b| per pixel and channel, times `scale`.
Image absolute_difference(const Image& a, const Image& b, double scale = 1.0);

}  // namespace metalfit::glpreview
