#include "bounce_maps.hpp"

#include <algorithm>

#include "../glossy_prefiltered/glossy_prefiltered_effect.hpp"
#include "glpreview/gl/uniforms.hpp"
#include "render/embedded_shaders.hpp"

namespace metalfit::glpreview {
namespace {

// As cube_direction() in cube_face.glsl: the direction of face coordinates (s, t) ∈ [−1, 1]².
Vec3 cube_direction(int face, double s, double t) {
    switch (face) {
        case 0: return {1, -t, -s};
        case 1: return {-1, -t, s};
        case 2: return {s, 1, t};
        case 3: return {s, -1, -t};
        case 4: return {s, -t, 1};
        default: return {-s, -t, -1};
    }
}

gl::Texture cube_array(int size, int layers, GLint filter) {
    gl::Texture texture = gl::create_texture(GL_TEXTURE_CUBE_MAP_ARRAY);
    glTextureStorage3D(texture.id(), 1, GL_RGBA32F, size, size, 6 * layers);
    glTextureParameteri(texture.id(), GL_TEXTURE_MIN_FILTER, filter);
    glTextureParameteri(texture.id(), GL_TEXTURE_MAG_FILTER, filter);
    return texture;
}

struct MapPrograms {
    const BuiltProgram& room;
    const BuiltProgram& sphere;  // sphere_hit.frag: a sphere's distance, normal and index
};

void draw_sphere_hits(const GpuRenderer& renderer, const BuiltProgram& program, int face,
                      const std::vector<std::size_t>& which, float sign, float depth_bias) {
    const Scene& scene = renderer.scene();
    glUseProgram(program.id());
    glBindVertexArray(renderer.vertex_array());
    set_uniform(program.id(), "u_face", face);
    set_uniform(program.id(), "u_depth_bias", depth_bias);
    for (const std::size_t j : which) {
        set_uniform(program.id(), "u_hit_center", scene.spheres[j].center);
        set_uniform(program.id(), "u_hit_radius", static_cast<float>(scene.spheres[j].radius));
        set_uniform(program.id(), "u_hit_index", sign * static_cast<float>(j + 1));
        glDrawArrays(GL_TRIANGLES, 0, 3);
    }
}

// Sphere i's layers, per face. The front layer: the room from its centre, the rough spheres (their own programs, as
// seen from the centre; index −(j + 1)) and the mirror spheres (distance, normal, index j + 1), nearest first by
// depth. The back layer (layer + layers): the room alone, where a ray behind a sphere of the front layer goes on.
void draw_layer(GpuRenderer& renderer, const MapPrograms& programs, std::size_t i, int layer, int layers,
                const BounceMaps& maps, const gl::Framebuffer& fbo) {
    const Scene& scene = renderer.scene();
    const Vec3 center = scene.spheres[i].center;
    std::vector<std::size_t> rough, mirrors;
    for (std::size_t j = 0; j < scene.spheres.size(); ++j)
        if (j != i) (scene.spheres[j].rough() ? rough : mirrors).push_back(j);
    const GLenum both[2] = {GL_COLOR_ATTACHMENT0, GL_COLOR_ATTACHMENT1};
    const GLenum hits_only[2] = {GL_NONE, GL_COLOR_ATTACHMENT1};
    const auto draw_room = [&](int face) {
        glDepthFunc(GL_ALWAYS);
        renderer.bind_environment(programs.room);
        glUseProgram(programs.room.id());
        glBindVertexArray(renderer.vertex_array());
        set_uniform(programs.room.id(), "u_face", face);
        glDrawArrays(GL_TRIANGLES, 0, 3);
    };
    for (int face = 0; face < 6; ++face) {
        glNamedFramebufferTextureLayer(fbo.id(), GL_COLOR_ATTACHMENT0, maps.radiance.id(), 0, 6 * layer + face);
        glNamedFramebufferTextureLayer(fbo.id(), GL_COLOR_ATTACHMENT1, maps.hits.id(), 0, 6 * layer + face);
        glNamedFramebufferDrawBuffers(fbo.id(), 2, both);
        if (glCheckNamedFramebufferStatus(fbo.id(), GL_FRAMEBUFFER) != GL_FRAMEBUFFER_COMPLETE)
            throw GlError("sphere " + std::to_string(i) + "'s distance map face " + std::to_string(face) +
                          " cannot be rendered to");
        glBindFramebuffer(GL_FRAMEBUFFER, fbo.id());
        glViewport(0, 0, maps.size, maps.size);
        const float none[4] = {0, 0, 0, 0}, far = 1.0f;
        glClearNamedFramebufferfv(fbo.id(), GL_COLOR, 1, none);
        glClearNamedFramebufferfv(fbo.id(), GL_DEPTH, 0, &far);
        glEnable(GL_DEPTH_TEST);
        glDepthMask(GL_TRUE);
        // The room and the rough spheres' radiance into the radiance layer only.
        glNamedFramebufferDrawBuffer(fbo.id(), GL_COLOR_ATTACHMENT0);
        draw_room(face);
        glDepthFunc(GL_LESS);
        if (!rough.empty()) {
            renderer.draw_spheres(cube_face_view(center, face), maps.size, maps.size, rough);
            // Their indices where they are the nearest (the same depth, a hair nearer; depth kept).
            glNamedFramebufferDrawBuffers(fbo.id(), 2, hits_only);
            glDepthFunc(GL_LEQUAL);
            glDepthMask(GL_FALSE);
            draw_sphere_hits(renderer, programs.sphere, face, rough, -1.0f, 1e-6f);
            glDepthMask(GL_TRUE);
            glDepthFunc(GL_LESS);
        }
        glNamedFramebufferDrawBuffers(fbo.id(), 2, both);
        draw_sphere_hits(renderer, programs.sphere, face, mirrors, 1.0f, 0.0f);
        // The back layer: the room alone.
        glNamedFramebufferTextureLayer(fbo.id(), GL_COLOR_ATTACHMENT0, maps.radiance.id(), 0,
                                       6 * (layer + layers) + face);
        glNamedFramebufferDrawBuffer(fbo.id(), GL_COLOR_ATTACHMENT0);
        draw_room(face);
    }
    glBindFramebuffer(GL_FRAMEBUFFER, 0);
}

// Rough sphere i's map: per face the room from its centre, then every other sphere with its own program.
void draw_rough_map(GpuRenderer& renderer, const BuiltProgram& room, std::size_t i, const EnvironmentCube& target,
                    const gl::Framebuffer& fbo) {
    const Scene& scene = renderer.scene();
    std::vector<std::size_t> others;
    for (std::size_t j = 0; j < scene.spheres.size(); ++j)
        if (j != i) others.push_back(j);
    for (int face = 0; face < 6; ++face) {
        glNamedFramebufferTexture(fbo.id(), GL_COLOR_ATTACHMENT1, 0, 0);
        glNamedFramebufferTextureLayer(fbo.id(), GL_COLOR_ATTACHMENT0, target.texture.id(), 0, face);
        glNamedFramebufferDrawBuffer(fbo.id(), GL_COLOR_ATTACHMENT0);
        if (glCheckNamedFramebufferStatus(fbo.id(), GL_FRAMEBUFFER) != GL_FRAMEBUFFER_COMPLETE)
            throw GlError("sphere " + std::to_string(i) + "'s radiance map face " + std::to_string(face) +
                          " cannot be rendered to");
        glBindFramebuffer(GL_FRAMEBUFFER, fbo.id());
        glViewport(0, 0, target.size, target.size);
        const float far = 1.0f;
        glClearNamedFramebufferfv(fbo.id(), GL_DEPTH, 0, &far);
        glEnable(GL_DEPTH_TEST);
        glDepthMask(GL_TRUE);
        glDepthFunc(GL_ALWAYS);
        renderer.bind_environment(room);
        glUseProgram(room.id());
        glBindVertexArray(renderer.vertex_array());
        set_uniform(room.id(), "u_face", face);
        glDrawArrays(GL_TRIANGLES, 0, 3);
        glDepthFunc(GL_LESS);
        renderer.draw_spheres(cube_face_view(scene.spheres[i].center, face), target.size, target.size, others);
    }
    glBindFramebuffer(GL_FRAMEBUFFER, 0);
    glGenerateTextureMipmap(target.texture.id());
}

}  // namespace

int bounce_map_size(const Scene& scene) { return std::min(scene.environment.cube_size, 256); }

CameraBasis cube_face_view(Vec3 center, int face) {
    const Vec3 forward = cube_direction(face, 0, 0);
    return {center, forward, cube_direction(face, 1, 0) - forward, cube_direction(face, 0, 1) - forward};
}

void render_bounce_maps(GpuRenderer& renderer, const BouncePlan& plan, BounceMaps& maps) {
    const Scene& scene = renderer.scene();
    maps.size = bounce_map_size(scene);
    maps.layer_of.assign(scene.spheres.size(), -1);
    for (std::size_t k = 0; k < plan.mapped.size(); ++k) maps.layer_of[plan.mapped[k]] = static_cast<int>(k);
    const int layers = static_cast<int>(plan.mapped.size());
    maps.layers = layers;
    std::vector<float> texels;  // row 0: centre and layer; row 1: radius
    for (std::size_t j = 0; j < scene.spheres.size(); ++j) {
        const Vec3 c = scene.spheres[j].center;
        texels.insert(texels.end(), {float(c.x), float(c.y), float(c.z), float(maps.layer_of[j])});
    }
    for (const Sphere& sphere : scene.spheres) texels.insert(texels.end(), {float(sphere.radius), 0.f, 0.f, 0.f});
    maps.spheres = gl::create_texture(GL_TEXTURE_2D);
    glTextureStorage2D(maps.spheres.id(), 1, GL_RGBA32F, static_cast<GLsizei>(scene.spheres.size()), 2);
    glTextureSubImage2D(maps.spheres.id(), 0, 0, 0, static_cast<GLsizei>(scene.spheres.size()), 2, GL_RGBA, GL_FLOAT,
                        texels.data());

    ShaderBuilder room("bounce-map-room");
    declare_environment(scene, room);
    room.source(shader_text("cube_face.glsl")).source(shader_text("sphere_map.frag"));
    ShaderBuilder sphere("bounce-map-sphere", ShaderBuilder::Stage::fragment);
    sphere.source(shader_text("cube_face.glsl")).source(shader_text("sphere_hit.frag"));
    const MapPrograms programs{renderer.program(room), renderer.program(sphere)};
    for (const BuiltProgram* p : {&programs.room, &programs.sphere}) set_uniform(p->id(), "u_size", maps.size);
    const gl::Framebuffer fbo = gl::create_framebuffer();
    const gl::Renderbuffer depth = gl::create_renderbuffer();
    glNamedRenderbufferStorage(depth.id(), GL_DEPTH_COMPONENT32F, maps.size, maps.size);
    glNamedFramebufferRenderbuffer(fbo.id(), GL_DEPTH_ATTACHMENT, GL_RENDERBUFFER, depth.id());
    if (layers > 0) {
        maps.radiance = cube_array(maps.size, 2 * layers, GL_LINEAR);
        maps.hits = cube_array(maps.size, layers, GL_NEAREST);  // an index is not interpolated
        for (const std::size_t i : plan.mapped) {
            for (const BuiltProgram* p : {&programs.room, &programs.sphere})
                set_uniform(p->id(), "u_map_center", scene.spheres[i].center);
            draw_layer(renderer, programs, i, maps.layer_of[i], layers, maps, fbo);
        }
    }
    maps.rough.clear();
    maps.rough.resize(scene.spheres.size());
    if (!plan.rough_mapped.empty()) {
        // The rough spheres' maps show the mirrors with their bounces: their programs find these maps.
        Blackboard& frame = renderer.frame();
        frame.put(maps);
        const PrefilteredCube* room_prefiltered = frame.find<PrefilteredCube>();
        for (const std::size_t i : plan.rough_mapped) {
            RoughMap& map = maps.rough[i].emplace(
                RoughMap{EnvironmentCube::create({maps.size, true, true}),
                         PrefilteredCube::create({PrefilteredCube::size_for(maps.size),
                                                  PrefilteredCube::levels_for(PrefilteredCube::size_for(maps.size))})});
            set_uniform(programs.room.id(), "u_map_center", scene.spheres[i].center);
            draw_rough_map(renderer, programs.room, i, map.radiance, fbo);
            prefilter_environment(renderer, map.radiance, map.prefiltered);
        }
        if (room_prefiltered) frame.put(*room_prefiltered);  // prefilter_environment put each rough map's there
    }
    check_gl("drawing the spheres' distance maps");
}

gl::Texture bounce_fresnel_table(const GpuRenderer& renderer) {
    const std::size_t rows = renderer.scene().spheres.size();
    std::vector<float> texels;
    for (std::size_t j = 0; j < rows; ++j)
        for (int k = 0; k < kBounceFresnelTexels; ++k) {
            const RGB f = renderer.fresnel(j)(static_cast<double>(k) / (kBounceFresnelTexels - 1));
            texels.insert(texels.end(), {float(f.r), float(f.g), float(f.b)});
        }
    gl::Texture table = gl::create_texture(GL_TEXTURE_2D);
    glTextureStorage2D(table.id(), 1, GL_RGB32F, kBounceFresnelTexels, static_cast<GLsizei>(rows));
    glTextureSubImage2D(table.id(), 0, 0, 0, kBounceFresnelTexels, static_cast<GLsizei>(rows), GL_RGB, GL_FLOAT,
                        texels.data());
    glTextureParameteri(table.id(), GL_TEXTURE_MIN_FILTER, GL_LINEAR);
    glTextureParameteri(table.id(), GL_TEXTURE_MAG_FILTER, GL_LINEAR);
    glTextureParameteri(table.id(), GL_TEXTURE_WRAP_S, GL_CLAMP_TO_EDGE);
    glTextureParameteri(table.id(), GL_TEXTURE_WRAP_T, GL_CLAMP_TO_EDGE);
    check_gl("uploading the bounces' Fresnel table");
    return table;
}

}  // namespace metalfit::glpreview
