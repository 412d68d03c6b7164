#include "glpreview/render/gpu_renderer.hpp"

#include <algorithm>
#include <stdexcept>

#include "embedded_shaders.hpp"
#include "glpreview/effects/registry.hpp"
#include "glpreview/gl/uniforms.hpp"
#include "glpreview/render/frame_inputs.hpp"
#include "glpreview/scene/camera.hpp"

namespace metalfit::glpreview {

GpuRenderer::GpuRenderer(const Scene& scene, const Features& features, std::vector<const SphereFresnel*> fresnel,
                         const Image* equirect, ProgramCache* programs)
    : scene_(scene),
      features_(features),
      fresnel_(std::move(fresnel)),
      own_programs_(programs ? std::nullopt : std::optional<ProgramCache>(std::in_place)),
      program_cache_(programs ? programs : &*own_programs_),
      vao_(gl::create_vertex_array()) {
    glEnable(GL_TEXTURE_CUBE_MAP_SEAMLESS);
    if (equirect) {
        own_equirect_.emplace(std::make_shared<const Image>(*equirect));
        equirect_ = &*own_equirect_;
        own_equirect_->id();
    }
    framebuffer_ = gl::create_framebuffer();
    color_ = gl::create_texture(GL_TEXTURE_2D);
    glTextureStorage2D(color_.id(), 1, GL_RGBA32F, scene.width, scene.height);
    depth_ = gl::create_renderbuffer();
    glNamedRenderbufferStorage(depth_.id(), GL_DEPTH_COMPONENT32F, scene.width, scene.height);
    glNamedFramebufferTexture(framebuffer_.id(), GL_COLOR_ATTACHMENT0, color_.id(), 0);
    glNamedFramebufferRenderbuffer(framebuffer_.id(), GL_DEPTH_ATTACHMENT, GL_RENDERBUFFER, depth_.id());
    if (glCheckNamedFramebufferStatus(framebuffer_.id(), GL_FRAMEBUFFER) != GL_FRAMEBUFFER_COMPLETE)
        throw GlError("the beauty framebuffer (RGBA32F + depth) is incomplete");
    check_gl("creating the renderer's textures");
}

void GpuRenderer::set_fresnel(std::size_t sphere, const SphereFresnel* fresnel) { fresnel_.at(sphere) = fresnel; }

void GpuRenderer::forget_fresnel(const SphereFresnel& fresnel) {
    for (const Effect* effect : all_effects()) effect->forget_fresnel(*this, fresnel);
}

const BuiltProgram& GpuRenderer::program(const ShaderBuilder& builder) {
    const std::string key = builder.key();
    if (auto it = programs_.find(key); it != programs_.end()) return it->second;
    // Linked once per context (another scene's renderer may have linked the same source); this scene's uniforms set
    // on its first use here (uniforms a shader lacks are ignored).
    const BuiltProgram& built = programs_.emplace(key, link(*program_cache_, builder)).first->second;
    set_camera_uniforms(built.id());
    for (const Effect* effect : all_effects()) effect->set_program_uniforms(scene_, built.id());
    return built;
}

std::vector<std::string> GpuRenderer::compiled_variants() const {
    std::vector<std::string> keys;
    for (const auto& [key, _] : programs_) keys.push_back(key);
    return keys;
}

namespace {

void set_view_uniforms(GLuint p, const CameraBasis& basis, int width, int height) {
    set_uniform(p, "u_camera_position", basis.position);
    set_uniform(p, "u_camera_forward", basis.forward);
    set_uniform(p, "u_camera_right", basis.right);
    set_uniform(p, "u_camera_up", basis.up);
    glProgramUniform2f(p, glGetUniformLocation(p, "u_viewport"), float(width), float(height));
}

}  // namespace

void GpuRenderer::set_camera_uniforms(GLuint p) const {
    set_view_uniforms(p, camera_basis(scene_.camera, scene_.width, scene_.height), scene_.width, scene_.height);
}

void GpuRenderer::bind_environment(const BuiltProgram& program) {
    if (cube_ && program.reads("u_env")) program.bind("u_env", cube_->texture.id());
    if (scene_.environment.type == EnvironmentType::equirect) {
        if (!equirect_) throw std::invalid_argument("GpuRenderer: the equirect image is missing");
        program.bind("u_equirect", equirect_->id());
    }
    for (const Effect* effect : all_effects()) effect->bind_environment_program(*this, program);
}

void GpuRenderer::draw_frame(bool diagnostics) {
    glBindFramebuffer(GL_FRAMEBUFFER, framebuffer_.id());
    glViewport(0, 0, scene_.width, scene_.height);
    glBindVertexArray(vao_.id());
    const float clear_depth = 1.0f;
    glClearNamedFramebufferfv(framebuffer_.id(), GL_DEPTH, 0, &clear_depth);

    glDisable(GL_DEPTH_TEST);
    glDepthMask(GL_FALSE);
    if (diagnostics) {
        const float zero[4] = {0, 0, 0, 0};
        glClearNamedFramebufferfv(framebuffer_.id(), GL_COLOR, 0, zero);
    } else {
        ShaderBuilder background("background");
        declare_environment(scene_, background);
        background.source(shader_text("camera.glsl")).source(shader_text("background.frag"));
        const BuiltProgram& p = program(background);
        bind_environment(p);
        glUseProgram(p.id());
        glDrawArrays(GL_TRIANGLES, 0, 3);
    }

    glEnable(GL_DEPTH_TEST);
    glDepthFunc(GL_LESS);
    glDepthMask(GL_TRUE);
    for (std::size_t i = 0; i < scene_.spheres.size(); ++i) draw_sphere(i, diagnostics);
    glBindFramebuffer(GL_FRAMEBUFFER, 0);
}

void GpuRenderer::draw_sphere(std::size_t i, bool diagnostics, const View* view) {
    const Sphere& sphere = scene_.spheres[i];
    const SphereFresnel& fresnel = *fresnel_[i];
    const BuiltProgram& p = program(sphere_shader(scene_, sphere, &fresnel, diagnostics));
    if (view) set_view_uniforms(p.id(), view->basis, view->width, view->height);
    set_uniform(p.id(), "u_sphere_center", sphere.center);
    set_uniform(p.id(), "u_sphere_radius", static_cast<float>(sphere.radius));
    bind_environment(p);
    const SphereDraw draw{scene_, sphere, fresnel, p, *this};
    for (const Effect* effect : all_effects()) effect->bind_sphere(draw);
    glUseProgram(p.id());
    glDrawArrays(GL_TRIANGLES, 0, 3);
    if (view) set_camera_uniforms(p.id());
}

void GpuRenderer::draw_spheres(const CameraBasis& view, int width, int height, std::span<const std::size_t> which) {
    glBindVertexArray(vao_.id());
    glEnable(GL_DEPTH_TEST);
    glDepthFunc(GL_LESS);
    glDepthMask(GL_TRUE);
    const View seen_from{view, width, height};
    for (const std::size_t i : which) {
        if (i >= scene_.spheres.size())
            throw std::out_of_range("GpuRenderer::draw_spheres: no sphere " + std::to_string(i));
        draw_sphere(i, false, &seen_from);
    }
}

Image GpuRenderer::render() {
    draw_frame();
    return read_frame();
}

Image GpuRenderer::read_frame() const {
    std::vector<float> rgba(static_cast<std::size_t>(scene_.width) * scene_.height * 4);
    glGetTextureImage(color_.id(), 0, GL_RGBA, GL_FLOAT, static_cast<GLsizei>(rgba.size() * sizeof(float)),
                      rgba.data());
    check_gl("reading a frame back");
    Image image(scene_.width, scene_.height);
    for (int y = 0; y < scene_.height; ++y)
        for (int x = 0; x < scene_.width; ++x) {
            const float* v = &rgba[4 * (static_cast<std::size_t>(y) * scene_.width + x)];
            image.set(x, scene_.height - 1 - y, {v[0], v[1], v[2]});
        }
    return image;
}

}  // namespace metalfit::glpreview

namespace metalfit::glpreview {

Blackboard& FrameInputs::frame_of(GpuRenderer& gpu) { return gpu.frame(); }

}  // namespace metalfit::glpreview
