#include "shadow_maps.hpp"

#include <algorithm>
#include <string>

#include "glpreview/gl/uniforms.hpp"
#include "glpreview/render/gpu_renderer.hpp"
#include "glpreview/render/sphere_shader.hpp"
#include "render/embedded_shaders.hpp"

namespace metalfit::glpreview {

ShadowMaps ShadowMaps::create(const Descriptor& d) {
    ShadowMaps maps{gl::create_texture(GL_TEXTURE_CUBE_MAP_ARRAY), gl::create_texture(GL_TEXTURE_2D_ARRAY), d.size};
    glTextureStorage3D(maps.cubes.id(), 1, GL_R32F, d.size, d.size, 6 * std::max(d.cubes, 1));
    glTextureStorage3D(maps.planes.id(), 1, GL_R32F, d.size, d.size, std::max(d.planes, 1));
    for (const GLuint texture : {maps.cubes.id(), maps.planes.id()}) {  // distances are compared, not blended
        glTextureParameteri(texture, GL_TEXTURE_MIN_FILTER, GL_NEAREST);
        glTextureParameteri(texture, GL_TEXTURE_MAG_FILTER, GL_NEAREST);
        glTextureParameteri(texture, GL_TEXTURE_WRAP_S, GL_CLAMP_TO_EDGE);
        glTextureParameteri(texture, GL_TEXTURE_WRAP_T, GL_CLAMP_TO_EDGE);
    }
    check_gl("creating the shadow maps");
    return maps;
}

void render_shadow_maps(GpuRenderer& renderer, const Lights& lights, const ShadowLayout& layout,
                        const ShadowMaps& maps) {
    const Scene& scene = renderer.scene();
    ShaderBuilder builder("shadow-map");
    declare_environment(scene, builder);
    builder.source(shader_text("cube_face.glsl")).source(shader_text("shadow_map.frag"));
    const BuiltProgram& p = renderer.program(builder);
    const GLuint id = p.id();
    const int occluders = static_cast<int>(std::min<std::size_t>(scene.spheres.size(), 256));
    set_uniform(id, "u_occluder_count", occluders);
    for (int i = 0; i < occluders; ++i) {
        const Sphere& s = scene.spheres[static_cast<std::size_t>(i)];
        glProgramUniform4f(id, glGetUniformLocation(id, ("u_occluders[" + std::to_string(i) + "]").c_str()),
                           float(s.center.x), float(s.center.y), float(s.center.z), float(s.radius));
    }
    set_uniform(id, "u_size", maps.size);
    const gl::Framebuffer fbo = gl::create_framebuffer();
    glUseProgram(id);
    glBindVertexArray(renderer.vertex_array());
    glDisable(GL_DEPTH_TEST);
    glViewport(0, 0, maps.size, maps.size);
    const auto draw_into = [&](GLuint texture, int layer) {
        glNamedFramebufferTextureLayer(fbo.id(), GL_COLOR_ATTACHMENT0, texture, 0, layer);
        if (glCheckNamedFramebufferStatus(fbo.id(), GL_FRAMEBUFFER) != GL_FRAMEBUFFER_COMPLETE)
            throw GlError("shadow map layer " + std::to_string(layer) + " cannot be rendered to");
        glBindFramebuffer(GL_FRAMEBUFFER, fbo.id());
        glDrawArrays(GL_TRIANGLES, 0, 3);
    };
    for (std::size_t i = 0; i < lights.lights.size(); ++i) {
        const Light& light = lights.lights[i];
        const int layer = layout.layer[i];
        if (layer < 0) continue;
        if (light.local()) {
            set_uniform(id, "u_light_origin", light.position);
            for (int face = 0; face < 6; ++face) {
                set_uniform(id, "u_face", face);
                draw_into(maps.cubes.id(), 6 * layer + face);
            }
        } else {
            const ShadowPlane plane = shadow_plane(scene.environment.room, light);
            set_uniform(id, "u_face", -1);
            set_uniform(id, "u_plane_origin", plane.origin);
            set_uniform(id, "u_plane_u", plane.axis_u);
            set_uniform(id, "u_plane_v", plane.axis_v);
            set_uniform(id, "u_plane_direction", plane.direction);
            draw_into(maps.planes.id(), layer);
        }
    }
    glBindFramebuffer(GL_FRAMEBUFFER, 0);
    check_gl("rendering the shadow maps");
}

}  // namespace metalfit::glpreview
