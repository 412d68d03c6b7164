// The indirect light on the GPU: the virtual lights gathered once per texel of the room faces' light maps
// (indirect_gather.frag; RoomLightMaps, radiance per unit albedo), which every program that reads the environment
// then looks up (indirect.glsl's indirect_on_surface).
#pragma once

#include <vector>

#include "glpreview/render/room_light_maps.hpp"
#include "virtual_lights.hpp"

namespace metalfit::glpreview {

class GpuRenderer;

// The indirect light's maps on the frame's blackboard under this name.
inline const char* const kIndirectLightName = "indirect-light";

// Uploads `lights` and gathers them into `maps`. Leaves the GL state it found.
void render_indirect_light_maps(GpuRenderer& renderer, const std::vector<VirtualLight>& lights,
                                const RoomLightMaps& maps);
// Whether render_indirect_light_maps is running on `renderer` (its program reads the environment too).
bool making_indirect_light(GpuRenderer& renderer);

}  // namespace metalfit::glpreview
