// The scene's "caustics" key (docs/scene.md, "Caustics"): how finely the caustic maps sample each light's view of a
// ring, how wide the Gaussian that splats their photons is, how fine the room's light maps are, and how many photons
// the CPU reference traces. Caustics are made whenever a light, a ring and a receiver in view exist; the key only
// tunes them.
#pragma once

#include "glpreview/scene/scene.hpp"
#include "glpreview/scene/scene_reader.hpp"

namespace metalfit::glpreview {

struct CausticSettings {
    int map_size = 128;          // caustic-map texels per edge, per light and ring: map_size² photons on the GPU
    double filter_width = 0.03;  // m: σ of the Gaussian each photon is splatted with (GPU) and density-estimated (CPU)
    int light_map_size = 256;    // texels per edge of each room face's light map
    int reference_photons = 1 << 20;  // photons the CPU reference traces per light and ring
};

// The "caustics" key, read strictly (map_size above the image limits, a width ≤ 0: errors naming the field).
CausticSettings read_caustic_settings(const SceneReader& top);

}  // namespace metalfit::glpreview
