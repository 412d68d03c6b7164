// The caustics on the GPU (docs/preview.md, "Caustics"): which light throws light through which ring (the plan, with
// its reasons for --explain), the room's light maps the photons are splatted into, and the passes that make them:
// the room's distance cube without the rings, one caustic map per light and ring (caustic_map.frag), its splat into
// each room face's light map (caustic_splat.vert/.frag).
#pragma once

#include <string>
#include <vector>

#include "caustic_settings.hpp"
#include "glpreview/render/room_light_maps.hpp"
#include "glpreview/scene/scene.hpp"

namespace metalfit::glpreview {

class GpuRenderer;

// One caustic map: a light (scene order) and a ring it can throw light through.
struct CausticJob {
    std::size_t light = 0, ring = 0;
};
struct CausticPlan {
    std::vector<CausticJob> jobs;  // empty: no caustic pass runs
    std::string why;               // what --explain says, either way
};
// The caustic maps of a scene: per light that throws caustics (point, spot, directional; a spot only when a ring lies
// in its cone) and per ring, when the room is there to receive them.
CausticPlan plan_caustics(const Scene& scene);
// The scene's settings (its "caustics" key, else the defaults).
CausticSettings caustic_settings(const Scene& scene);

// The caustics' light maps (RoomLightMaps) hold irradiance (W/m²); on the frame's blackboard under this name.
inline const char* const kCausticLightName = "caustic-light";

// Renders every job of `plan` and splats it into `maps` (cleared first). Leaves the GL state it found.
void render_caustic_light_maps(GpuRenderer& renderer, const CausticPlan& plan, const CausticSettings& settings,
                               const RoomLightMaps& maps);

// Whether render_caustic_light_maps is running on `renderer` (its own programs read the environment too, without the
// light maps they are making).
bool making_caustics(GpuRenderer& renderer);

}  // namespace metalfit::glpreview
