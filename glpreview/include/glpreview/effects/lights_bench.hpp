// What lights cost on the GPU (`glpreview --bench-lights`): in the glossy benchmark's room (gold, reference Fresnel,
// 128², quick: 48²), frames of a rough sphere (roughness 0.3, prefiltered) without lights and with 1 and 4 point
// lights, and the shadow pass of one light (a 256² distance cube map: six faces), each timed interleaved with the
// mirror frame (the same sphere at roughness 0, classic, no light) in one run; ratios to it with their noise.
// Implemented in src/effects/lights/.
#pragma once

#include <nlohmann/json.hpp>

#include "glpreview/gl/gl_context.hpp"
#include "glpreview/render/preview.hpp"

namespace metalfit::glpreview {

// {"renderer", "size", "rounds", "rows": [{"variant", "ms", "ratio_to_mirror_frame", "ratio_noise"}],
//  "light_pass_per_light", "shadow_pass_per_light"}: the last two as ratios to the mirror frame.
nlohmann::ordered_json bench_lights(GlContext& context, const PreviewOptions& options, bool quick);

}  // namespace metalfit::glpreview
