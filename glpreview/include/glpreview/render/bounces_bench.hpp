// The compounding table (`glpreview --bench-bounces`): how the cheap Fresnel models' errors grow bounce by bounce.
// A fixed scene — gold, copper, silver and aluminium mirror spheres 0.1 apart in a 2 × 2 square, in the default room
// with a ceiling panel, seen from the front and above — is rendered on the CPU (render/bounce_orders.hpp: the mirror
// paths cut at bounce order k = 1 … 4) for every model of libfit's registry with its fitted and its closed-form
// parameters (where the model defines a closed form for all four metals), as the preview uses them; each against the
// RGB reference (the reference LUTs along the same paths) and the spectral reference, over every sphere's pixels.
// CPU only: no GL context is opened.
#pragma once

#include <nlohmann/json.hpp>

#include "glpreview/render/preview.hpp"
#include "glpreview/scene/scene.hpp"

namespace metalfit::glpreview {

inline constexpr int kBenchBounceOrders = 4;

// The bench scene (quick: 96 × 72, else 256 × 192), every sphere's Fresnel the reference.
Scene bounces_bench_scene(bool quick);

// {"scene", "size", "orders", "rgb_vs_spectral": [{order, rmse, de2000_mean, de2000_p95, reaching}],
//  "rows": [{model, params, order, rmse, de2000_mean, de2000_p95, "vs_spectral": {rmse, de2000_mean, de2000_p95},
//            reaching, reaching_vs_spectral}], "skipped": [{model, params, why}]}
// The errors are over every sphere pixel; `reaching` ({rmse, de2000_mean, de2000_p95, pixels}) over the pixels whose
// mirror path reaches bounce `order` (it met another sphere at each bounce before): where the compounding shows.
nlohmann::ordered_json bench_bounces(const PreviewOptions& options, bool quick);

}  // namespace metalfit::glpreview
