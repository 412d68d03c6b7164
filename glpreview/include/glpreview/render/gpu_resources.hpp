// The GL resources passes hand to each other through the pass graph, each made from a descriptor (or, for an
// upload of CPU data, on its first GPU use) and freed with its handle.
#pragma once

#include <memory>

#include "glpreview/gl/objects.hpp"
#include "glpreview/io/image.hpp"

namespace metalfit::glpreview {

// The captured environment: radiance and, when some sphere uses the distance impostor, the distance in alpha.
struct EnvironmentCube {
    struct Descriptor {
        int size = 256;         // texels per face edge
        bool distance = false;  // float32 (distances need it: half floats keep 11 bits), else RGBA16F
        bool mipmaps = false;   // a full mip chain (made after the capture), read by the prefilter's filtered sampling
    };
    static EnvironmentCube create(const Descriptor& descriptor);
    gl::Texture texture;
    int size = 0;
    int levels = 1;
};

// The GGX-prefiltered radiance cube: level k holds the environment convolved with the lobe of roughness
// k / (levels − 1) (level 0: the environment itself), RGBA16F. Made from the captured cube by the prefilter pass.
struct PrefilteredCube {
    struct Descriptor {
        int size = 256;  // level 0's texels per face edge (the captured cube's)
        int levels = 6;  // one mip level per roughness step
    };
    static PrefilteredCube create(const Descriptor& descriptor);
    // Level 0's size for a captured cube of `cube_size`: the same, at most kMaxSize (the prefilter's cost).
    static constexpr int kMaxSize = 512;
    static int size_for(int cube_size) { return cube_size < kMaxSize ? cube_size : kMaxSize; }
    // The levels of a cube of `size`: 6, or fewer when the size does not halve that often (at least 2×2 texels).
    static int levels_for(int size);
    gl::Texture texture;
    int size = 0;
    int levels = 0;
};

// The captured cube downsampled to M × M texels per face (thesis ch. 5), each texel an area light: two 2D RGBA32F
// textures of 6M × M texels (texel (face · M + i, j) covers the source texels of face `face`, columns
// [i S/M, (i+1) S/M) and rows [j S/M, (j+1) S/M)): the average radiance and the average position (relative to the
// reference point) of the source texels it covers.
struct DownsampledCube {
    struct Descriptor {
        int m = 8;
    };
    static DownsampledCube create(const Descriptor& descriptor);
    gl::Texture radiance, position;
    int m = 0;
};

// An image environment at infinity as an RGB32F texture, uploaded from the loaded image on its first GPU use
// (so that a scene with no GPU pass opens no GL context).
class EquirectTexture {
public:
    explicit EquirectTexture(std::shared_ptr<const Image> image) : image_(std::move(image)) {}
    GLuint id() const;  // uploads on the first call (needs a current context)

private:
    std::shared_ptr<const Image> image_;
    mutable gl::Texture texture_;
};

}  // namespace metalfit::glpreview
