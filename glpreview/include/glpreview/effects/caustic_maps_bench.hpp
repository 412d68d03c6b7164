// What caustics cost on the GPU (`glpreview --bench-caustic-maps`): in the shipped ring scene
// (data/scenes/ring-caustic.json: a gold half ring under a grazing directional light; quick: 160×120), one light's
// caustic map and its splat into the room's six light maps at the distance-impostor article's sizes (32² photons into
// 256² light maps; a 64² caustic map) and finer ones, each timed interleaved with the scene's mirror frame in one run;
// ratios to it with their noise. Implemented in src/effects/caustics/.
#pragma once

#include <nlohmann/json.hpp>

#include "glpreview/gl/gl_context.hpp"
#include "glpreview/render/preview.hpp"

namespace metalfit::glpreview {

// {"renderer", "size", "rounds", "rows": [{"variant", "photons", "light_map_size", "ms", "ratio_to_mirror_frame",
//  "ratio_noise"}]}
nlohmann::ordered_json bench_caustic_maps(GlContext& context, const PreviewOptions& options, bool quick);

}  // namespace metalfit::glpreview
