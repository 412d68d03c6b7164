#include "glpreview/render/gpu_resources.hpp"

#include "glpreview/gl/gl_context.hpp"

namespace metalfit::glpreview {

EnvironmentCube EnvironmentCube::create(const Descriptor& d) {
    int levels = 1;
    if (d.mipmaps)
        while ((d.size >> levels) > 0) ++levels;
    EnvironmentCube cube{gl::create_texture(GL_TEXTURE_CUBE_MAP), d.size, levels};
    glTextureStorage2D(cube.texture.id(), levels, d.distance ? GL_RGBA32F : GL_RGBA16F, d.size, d.size);
    glTextureParameteri(cube.texture.id(), GL_TEXTURE_MIN_FILTER, levels > 1 ? GL_LINEAR_MIPMAP_LINEAR : GL_LINEAR);
    glTextureParameteri(cube.texture.id(), GL_TEXTURE_MAG_FILTER, GL_LINEAR);
    check_gl("creating the environment cube map");
    return cube;
}

int PrefilteredCube::levels_for(int size) {
    int levels = 1;
    while (levels < 6 && (size >> levels) >= 2) ++levels;
    return levels;
}

PrefilteredCube PrefilteredCube::create(const Descriptor& d) {
    PrefilteredCube cube{gl::create_texture(GL_TEXTURE_CUBE_MAP), d.size, d.levels};
    glTextureStorage2D(cube.texture.id(), d.levels, GL_RGBA16F, d.size, d.size);
    glTextureParameteri(cube.texture.id(), GL_TEXTURE_MIN_FILTER, GL_LINEAR_MIPMAP_LINEAR);
    glTextureParameteri(cube.texture.id(), GL_TEXTURE_MAG_FILTER, GL_LINEAR);
    glTextureParameteri(cube.texture.id(), GL_TEXTURE_MAX_LEVEL, d.levels - 1);
    check_gl("creating the prefiltered cube map");
    return cube;
}

DownsampledCube DownsampledCube::create(const Descriptor& d) {
    DownsampledCube cube{gl::create_texture(GL_TEXTURE_2D), gl::create_texture(GL_TEXTURE_2D), d.m};
    for (const gl::Texture* t : {&cube.radiance, &cube.position}) {
        glTextureStorage2D(t->id(), 1, GL_RGBA32F, 6 * d.m, d.m);
        glTextureParameteri(t->id(), GL_TEXTURE_MIN_FILTER, GL_NEAREST);
        glTextureParameteri(t->id(), GL_TEXTURE_MAG_FILTER, GL_NEAREST);
    }
    check_gl("creating the downsampled cube");
    return cube;
}

GLuint EquirectTexture::id() const {
    if (!texture_) {
        texture_ = gl::create_texture(GL_TEXTURE_2D);
        glTextureStorage2D(texture_.id(), 1, GL_RGB32F, image_->width, image_->height);
        glTextureSubImage2D(texture_.id(), 0, 0, 0, image_->width, image_->height, GL_RGB, GL_FLOAT,
                            image_->rgb.data());
        check_gl("uploading the equirect image");
    }
    return texture_.id();
}

}  // namespace metalfit::glpreview
