// The scene's "indirect" key (docs/scene.md, "Indirect light"): the diffuse light the room reflects once more, by
// virtual light sources. Asked for by the key alone; without it nothing of it is planned.
#pragma once

#include "glpreview/scene/scene_reader.hpp"

namespace metalfit::glpreview {

struct IndirectSettings {
    int paths = 256;               // light paths shot per light
    double clamp_distance = 0.25;  // m: the thesis's distance clamp (eq. 6.1 divides by at least its square)
    double evaluation_rate = 0.9;  // shadow rays for the largest potentials until they hold this share of the total
    int reference_samples = 64;    // cosine-weighted directions per point of the CPU reference (Monte Carlo)
    int light_map_size = 64;       // texels per edge of each room face's light map the GPU gathers into
};

// The "indirect" key, read strictly (errors name the file and the field).
IndirectSettings read_indirect_settings(const SceneReader& top);

}  // namespace metalfit::glpreview
