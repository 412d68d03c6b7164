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
    };
    static EnvironmentCube create(const Descriptor& descriptor);
    gl::Texture texture;
    int size = 0;
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
