// The caustics on the GPU (docs/preview.md, "Caustics"): which light throws light through which ring (the plan, with
// its reasons for --explain), the room's light maps the photons are splatted into, and the passes that make them:
// the room's distance cube without the rings, one caustic map per light and ring (caustic_map.frag), its splat into
// each room face's light map (caustic_splat.vert/.frag).
#pragma once

#include <string>
#include <vector>

#include "caustic_settings.hpp"
#include "glpreview/gl/objects.hpp"
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

// The room's six light maps: a 2D texture array, layer 2·axis + side (side 0: the min plane), RGBA32F, each texel
// the caustic irradiance (W/m²) at its centre; u and v run along the face's two other axes in x, y, z order.
struct CausticLightMaps {
    struct Descriptor {
        int size = 256;
    };
    static CausticLightMaps create(const Descriptor& descriptor);
    gl::Texture texture;
    int size = 0;
};

// Renders every job of `plan` and splats it into `maps` (cleared first). Leaves the GL state it found.
void render_caustic_light_maps(GpuRenderer& renderer, const CausticPlan& plan, const CausticSettings& settings,
                               const CausticLightMaps& maps);

// Whether render_caustic_light_maps is running on `renderer` (its own programs read the environment too, without the
// light maps they are making).
bool making_caustics(GpuRenderer& renderer);

// The caustic light maps read back, layer by layer (rgb per texel, row 0 at v = 0): tests and metrics.
std::vector<std::vector<float>> read_light_maps(const CausticLightMaps& maps);

}  // namespace metalfit::glpreview
