// The spectral reference: the analytic reference's mirror paths (render/mirror_path.hpp), with the spectral
// F(λ, μ_k) of every bounce's material multiplied per wavelength before the product meets the light and is turned
// into RGB — next to the RGB reference, which multiplies the per-bounce RGB reflectances R_c(μ_k). The light at the
// end of a path (the environment's RGB radiance, or an emitter's) is lifted to a spectrum by RgbUplift; the result
// is integrated with the CMFs under the scene's illuminant and converted to its working space as libfit converts
// the reflectance curves (white balanced). Pixels of the environment keep its RGB radiance. Rough spheres are
// mirrors here.
#pragma once

#include <vector>

#include "glpreview/render/cpu_lighting.hpp"
#include "glpreview/render/cpu_reference.hpp"
#include "glpreview/render/environment.hpp"
#include "glpreview/render/rgb_uplift.hpp"
#include "glpreview/render/spectral_fresnel.hpp"
#include "glpreview/scene/scene.hpp"

namespace metalfit::glpreview {

// spectral[i] belongs to scene.spheres[i]; max_bounces 1 … 8 (std::invalid_argument otherwise).
ReferenceRender render_spectral_reference(const Scene& scene, const std::vector<const SpectralFresnel*>& spectral,
                                          const RgbUplift& uplift, const EnvironmentTracer& environment,
                                          int max_bounces, int threads = 0, const CpuLighting* lighting = nullptr);

}  // namespace metalfit::glpreview
