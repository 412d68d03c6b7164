// GpuRenderer's environment job: the capture of the environment into a cube map, and, without a pass graph, what
// every registered effect derives from it.
#include <stdexcept>

#include "embedded_shaders.hpp"
#include "glpreview/effects/registry.hpp"
#include "glpreview/gl/uniforms.hpp"
#include "glpreview/render/gpu_renderer.hpp"

namespace metalfit::glpreview {

EnvironmentCube::Descriptor GpuRenderer::cube_descriptor() const {
    return {scene_.environment.cube_size, features_.distance_channel, features_.prefiltered_map};
}

void GpuRenderer::capture_environment() {
    if (!features_.environment_capture) return;
    if (!own_cube_) own_cube_ = EnvironmentCube::create(cube_descriptor());
    capture_environment(*own_cube_);
    for (const Effect* effect : all_effects()) effect->derive_from_environment(*this, *own_cube_);
}

void GpuRenderer::capture_environment(const EnvironmentCube& cube) {
    const int n = cube.size;
    ShaderBuilder capture("capture");
    declare_environment(scene_, capture);
    capture.source(shader_text("cube_face.glsl")).source(shader_text("capture.frag"));
    const BuiltProgram& p = program(capture);
    set_uniform(p.id(), "u_size", n);
    const gl::Framebuffer fbo = gl::create_framebuffer();
    bind_environment(p);  // an equirect on its proxy: the image is painted on it; the effects' light on the room
    glUseProgram(p.id());
    glBindVertexArray(vao_.id());
    glDisable(GL_DEPTH_TEST);
    glViewport(0, 0, n, n);
    for (int face = 0; face < 6; ++face) {
        glNamedFramebufferTextureLayer(fbo.id(), GL_COLOR_ATTACHMENT0, cube.texture.id(), 0, face);
        if (glCheckNamedFramebufferStatus(fbo.id(), GL_FRAMEBUFFER) != GL_FRAMEBUFFER_COMPLETE)
            throw GlError("cube-map face " + std::to_string(face) + " cannot be rendered to");
        glBindFramebuffer(GL_FRAMEBUFFER, fbo.id());
        set_uniform(p.id(), "u_face", face);
        glDrawArrays(GL_TRIANGLES, 0, 3);
    }
    glBindFramebuffer(GL_FRAMEBUFFER, 0);
    if (cube.levels > 1) glGenerateTextureMipmap(cube.texture.id());
    check_gl("capturing the environment");
    cube_ = &cube;
}

}  // namespace metalfit::glpreview
