#include "indirect_light_maps.hpp"

#include <algorithm>
#include <cstring>

#include "glpreview/gl/saved_gl_state.hpp"
#include "glpreview/gl/uniforms.hpp"
#include "glpreview/render/gpu_renderer.hpp"
#include "glpreview/render/sphere_shader.hpp"
#include "render/embedded_shaders.hpp"

namespace metalfit::glpreview {
namespace {

struct IndirectInProgress {
    bool active = false;
    struct Scope {  // active while it lives
        explicit Scope(IndirectInProgress& state) : state_(state) { state_.active = true; }
        ~Scope() { state_.active = false; }
        IndirectInProgress& state_;
    };
};

// The virtual lights as a texture: column i, rows position, normal, intensity.
gl::Texture upload(const std::vector<VirtualLight>& lights) {
    const auto count = static_cast<GLsizei>(std::max<std::size_t>(lights.size(), 1));
    std::vector<float> texels(static_cast<std::size_t>(count) * 3 * 4, 0.0f);
    for (std::size_t i = 0; i < lights.size(); ++i) {
        const VirtualLight& v = lights[i];
        const float rows[3][4] = {{float(v.position.x), float(v.position.y), float(v.position.z), 1},
                                  {float(v.normal.x), float(v.normal.y), float(v.normal.z), 0},
                                  {float(v.intensity.r), float(v.intensity.g), float(v.intensity.b), 0}};
        for (std::size_t row = 0; row < 3; ++row)
            std::memcpy(&texels[(row * static_cast<std::size_t>(count) + i) * 4], rows[row], sizeof rows[row]);
    }
    gl::Texture texture = gl::create_texture(GL_TEXTURE_2D);
    glTextureStorage2D(texture.id(), 1, GL_RGBA32F, count, 3);
    glTextureSubImage2D(texture.id(), 0, 0, 0, count, 3, GL_RGBA, GL_FLOAT, texels.data());
    glTextureParameteri(texture.id(), GL_TEXTURE_MIN_FILTER, GL_NEAREST);
    glTextureParameteri(texture.id(), GL_TEXTURE_MAG_FILTER, GL_NEAREST);
    check_gl("uploading the virtual lights");
    return texture;
}

}  // namespace

bool making_indirect_light(GpuRenderer& renderer) { return renderer.frame().state<IndirectInProgress>().active; }

void render_indirect_light_maps(GpuRenderer& renderer, const std::vector<VirtualLight>& lights,
                                const RoomLightMaps& maps) {
    const SavedGlState saved;
    const IndirectInProgress::Scope in_progress(renderer.frame().state<IndirectInProgress>());

    const gl::Texture texture = upload(lights);
    ShaderBuilder builder("indirect-gather");
    declare_environment(renderer.scene(), builder);
    builder.source(shader_text("indirect_gather.frag"));
    const BuiltProgram& p = renderer.program(builder);
    renderer.bind_environment(p);  // the rings (their shadow rays)
    p.bind("u_virtual_lights", texture.id());
    set_uniform(p.id(), "u_virtual_light_count", static_cast<int>(lights.size()));
    set_uniform(p.id(), "u_size", maps.size);
    glUseProgram(p.id());
    glBindVertexArray(renderer.vertex_array());
    glDisable(GL_DEPTH_TEST);
    glDisable(GL_BLEND);
    glViewport(0, 0, maps.size, maps.size);
    const gl::Framebuffer fbo = gl::create_framebuffer();
    for (int face = 0; face < 6; ++face) {
        set_uniform(p.id(), "u_face", face);
        glNamedFramebufferTextureLayer(fbo.id(), GL_COLOR_ATTACHMENT0, maps.texture.id(), 0, face);
        if (glCheckNamedFramebufferStatus(fbo.id(), GL_FRAMEBUFFER) != GL_FRAMEBUFFER_COMPLETE)
            throw GlError("an indirect light map cannot be rendered to");
        glBindFramebuffer(GL_FRAMEBUFFER, fbo.id());
        glDrawArrays(GL_TRIANGLES, 0, 3);
    }
    check_gl("gathering the indirect light");
}

}  // namespace metalfit::glpreview
