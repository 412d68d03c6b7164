// What inter-reflections cost on the GPU (`glpreview --bench-interreflections`): four mirror spheres (gold,
// copper, silver, aluminium, the exact reference Fresnel) close enough to reflect each other in the default room,
// 256² (quick: 96²), distance maps of 256² (quick: 64²); the frame at max_bounces 2, 3 and 4 (its maps made
// beforehand: a static scene makes them once) and the making of one sphere's map (six faces: the room and the three
// other spheres), each timed interleaved with the one-bounce frame of the same spheres in one run; ratios to it
// with their noise. Implemented in src/effects/interreflections/.
#pragma once

#include <nlohmann/json.hpp>

#include "glpreview/gl/gl_context.hpp"
#include "glpreview/render/preview.hpp"
#include "glpreview/scene/scene.hpp"

namespace metalfit::glpreview {

// The benchmark's scene at `bounces` (its spheres: Au, Cu, Ag, Al on a square, 0.1 m apart at their closest).
Scene interreflections_bench_scene(bool quick, int bounces);

// {"renderer", "size", "map_size", "rounds", "rows": [{"variant", "ms", "ratio_to_one_bounce_frame",
//  "ratio_noise"}], "map_update_per_sphere": {"ratio_to_one_bounce_frame", "ratio_noise"}}.
nlohmann::ordered_json bench_interreflections(GlContext& context, const PreviewOptions& options, bool quick);

}  // namespace metalfit::glpreview
