// The lights' shadow maps on the GPU: distance cube maps (one cube-array layer per local light that casts) and
// distance planes (one 2D-array layer per directional light that casts), R32F, each texel the distance to the first
// occluder along its ray (shadow_map.frag).
#pragma once

#include "glpreview/gl/objects.hpp"
#include "light.hpp"

namespace metalfit::glpreview {

class GpuRenderer;

struct ShadowMaps {
    struct Descriptor {
        int size = kShadowMapSize;
        int cubes = 0;  // layers (at least one is made, so the samplers always have a texture)
        int planes = 0;
    };
    static ShadowMaps create(const Descriptor& descriptor);
    gl::Texture cubes;   // GL_TEXTURE_CUBE_MAP_ARRAY
    gl::Texture planes;  // GL_TEXTURE_2D_ARRAY
    int size = 0;
};

// Renders every light's map of `layout` into `maps` (the renderer's scene: its spheres and room boxes occlude).
void render_shadow_maps(GpuRenderer& renderer, const Lights& lights, const ShadowLayout& layout,
                        const ShadowMaps& maps);

}  // namespace metalfit::glpreview
