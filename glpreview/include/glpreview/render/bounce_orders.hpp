// The errors of a scene with max_bounces > 1 split by bounce order. The image of order k is the CPU reference
// rendered with max_bounces = k (every path cut after k reflections, its last ray taking the environment's radiance),
// three times: with each sphere's own Fresnel (its model, or its reference LUT), with every sphere's reference LUT
// (the RGB reference: the product of per-bounce RGB reflectances R_c(μ_i)), and spectrally (render/
// spectral_reference.hpp: the product of F(λ, μ_i) turned into RGB at the end). Per sphere (the pixels where the
// camera sees it) and order: the model's error (own Fresnel vs RGB reference), the RGB rendering's error (RGB vs
// spectral reference: what no fit removes) and their sum (own Fresnel vs spectral), each as the RMSE of linear
// radiance and the ΔE2000 mean and 95th percentile. Mirror paths: a rough sphere is traced as a mirror here.
#pragma once

#include <cstddef>
#include <vector>

#include <nlohmann/json.hpp>

#include "glpreview/render/cpu_lighting.hpp"
#include "glpreview/render/cpu_reference.hpp"
#include "glpreview/render/delta_e_view.hpp"
#include "glpreview/render/rgb_uplift.hpp"
#include "glpreview/render/spectral_fresnel.hpp"

namespace metalfit::glpreview {

// What the three renders of an order use; [i] belongs to scene.spheres[i].
struct BounceFresnel {
    std::vector<const SphereFresnel*> own = {};        // the sphere's own Fresnel (its model or its LUT)
    std::vector<const SphereFresnel*> reference = {};  // its material's reference LUT
    std::vector<const SpectralFresnel*> spectral = {};
    const RgbUplift* uplift = nullptr;
};

struct BounceOrderRenders {
    ReferenceRender own, rgb, spectral;
};
BounceOrderRenders render_bounce_order(const Scene& scene, const BounceFresnel& fresnel,
                                       const EnvironmentTracer& environment, int order, int threads = 0,
                                       const CpuLighting* lighting = nullptr);

// One image against another over a mask (NaN where the mask is empty).
struct MaskedError {
    double rmse = 0;         // linear radiance, over the pixels and channels
    double de2000_mean = 0;  // CIEDE2000 per pixel (render/delta_e_view)
    double de2000_p95 = 0;
    std::size_t pixels = 0;
};
// Per sphere of `mask` (its sphere_id), `image` against `reference`.
std::vector<MaskedError> masked_errors(const Image& image, const Image& reference, const ReferenceRender& mask,
                                       std::size_t spheres, const DeltaEBasis& basis);

// Every sphere pixel of `render` as one mask (sphere 0), and the pixels whose mirror path reaches bounce `order` (it
// meets another sphere at every bounce before) as one mask: where compounding shows.
ReferenceRender sphere_pixels_mask(const ReferenceRender& render);
ReferenceRender reaching_mask(const Scene& scene, const ReferenceRender& render, int order);

struct SphereOrderError {
    MaskedError model;              // own Fresnel vs RGB reference
    MaskedError rgb_vs_spectral;    // RGB reference vs spectral reference
    MaskedError model_vs_spectral;  // own Fresnel vs spectral reference
};
// [sphere] of one order's renders.
std::vector<SphereOrderError> bounce_order_errors(const BounceOrderRenders& renders, std::size_t spheres,
                                                  const DeltaEBasis& basis);

// metrics.json's "bounce_orders" of one sphere: [{order, model, rgb_vs_spectral, model_vs_spectral}], each error
// {rmse, de2000_mean, de2000_p95}; `orders[k - 1]` is order k's errors of every sphere.
nlohmann::ordered_json bounce_orders_json(const std::vector<std::vector<SphereOrderError>>& orders, std::size_t sphere);
nlohmann::ordered_json masked_error_json(const MaskedError& e);

}  // namespace metalfit::glpreview
