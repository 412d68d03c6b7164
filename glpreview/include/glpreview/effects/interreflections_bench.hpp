// What inter-reflections cost on the GPU (`glpreview --bench-interreflections`): the compounding table's scene
// (render/bounces_bench.hpp: gold, copper, silver and aluminium mirrors 0.1 apart, the exact reference Fresnel, the
// distance impostor), 256 × 192 (quick: 96 × 72), distance maps of 256² (quick: 64²); the frame at max_bounces 2, 3 and 4 (its maps made
// beforehand: a static scene makes them once) and the making of one sphere's map (six faces: the room and the three
// other spheres), each timed interleaved with the one-bounce frame of the same spheres in one run; ratios to it
// with their noise. Each frame is compared with the CPU reference of its bounce count (exact ray–sphere paths):
// over every sphere pixel, and over the pixels whose path reaches its last bounce. Implemented in
// src/effects/interreflections/.
#pragma once

#include <nlohmann/json.hpp>

#include "glpreview/gl/gl_context.hpp"
#include "glpreview/render/preview.hpp"
#include "glpreview/scene/scene.hpp"

namespace metalfit::glpreview {

// The benchmark's scene at `bounces`.
Scene interreflections_bench_scene(bool quick, int bounces);

// {"renderer", "size", "map_size", "rounds", "rows": [{"variant", "ms", "ratio_to_one_bounce_frame", "ratio_noise",
//  "vs_reference", "vs_reference_reaching": {rmse, de2000_mean, de2000_p95}, "reaching_pixels"}],
//  "map_update_per_sphere": {"ms", "ratio_to_one_bounce_frame", "ratio_noise"}}.
nlohmann::ordered_json bench_interreflections(GlContext& context, const PreviewOptions& options, bool quick);

}  // namespace metalfit::glpreview
