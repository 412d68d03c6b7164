// The per-model caustic table (`glpreview --bench-caustics`, issue 35 item 5; docs/preview.md, "Caustics: the
// reference and the per-model table"): a gold, a copper and an aluminium ring (radius 1 m, 0.35 m tall, a half
// circle) in the default room under a grazing directional light (elevation atan 0.35 ≈ 19°, 3 W/m², white); the
// photons are traced once (their paths do not depend on the Fresnel) and weighed with the exact spectral Fresnel
// (the reference), the RGB reference curve and every model of libfit's registry with its fitted and closed-form
// parameters. Per row: the caustic's total power (every receiver), its floor peak irradiance (at the reference's
// peak) and its colour (each channel's share of the power), as relative errors against the spectral reference.
// CPU only: no GL context is opened.
#pragma once

#include <nlohmann/json.hpp>

#include "glpreview/render/preview.hpp"

namespace metalfit::glpreview {

// {"scene", "light", "photons", "filter_width", "metals": [{"metal", "source", "reference": {power, power_after_several_reflections, peak_irradiance,
//  peak_position, focus, focus_distance}, "rows": [{model, params, power, peak_irradiance, power_rel, peak_rel,
//  colour_rel, peak_shift}], "skipped": [{model, params, why}]}]}. Relative errors are per channel (R, G, B) and
// `worst` (the channel of largest magnitude, with its sign).
nlohmann::ordered_json bench_caustics(const PreviewOptions& options, bool quick);

}  // namespace metalfit::glpreview
