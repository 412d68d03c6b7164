#include "glpreview/render/gpu_renderer.hpp"

#include <algorithm>
#include <stdexcept>

#include "embedded_shaders.hpp"
#include "frame_timing.hpp"
#include "glpreview/scene/camera.hpp"
#include "libfit/models/model.hpp"

namespace metalfit::glpreview {
namespace {

void set(GLuint program, const char* name, Vec3 v) {
    glProgramUniform3f(program, glGetUniformLocation(program, name), static_cast<float>(v.x), static_cast<float>(v.y),
                       static_cast<float>(v.z));
}
void set(GLuint program, const char* name, const RGB& v) {
    glProgramUniform3f(program, glGetUniformLocation(program, name), static_cast<float>(v.r), static_cast<float>(v.g),
                       static_cast<float>(v.b));
}
void set(GLuint program, const char* name, float v) { glProgramUniform1f(program, glGetUniformLocation(program, name), v); }
void set(GLuint program, const char* name, int v) { glProgramUniform1i(program, glGetUniformLocation(program, name), v); }

// "FRESNEL_MODEL f82-tint" is a plan-level name; the shader gets FRESNEL_MODEL alone plus the model's GLSL.
std::string define_line(const std::string& define) {
    if (define.rfind("FRESNEL_MODEL", 0) == 0) return "#define FRESNEL_MODEL\n";
    return "#define " + define + "\n";
}

}  // namespace

std::string model_call(const Model& model) {
    std::string call = std::string(model.glsl_function()) + "(";
    for (std::size_t k = 0; k < model.parameters().size(); ++k) call += "u_param[" + std::to_string(k) + "], ";
    return call + "mu)";
}

void set_model_parameters(GLuint program, const Model& model, const ModelParameters& params) {
    for (std::size_t k = 0; k < model.parameters().size(); ++k)
        set(program, ("u_param[" + std::to_string(k) + "]").c_str(), Vec3{params[0][k], params[1][k], params[2][k]});
}

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
    for (const SphereFresnel* f : fresnel_) upload_lut(f);
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

void GpuRenderer::upload_lut(const SphereFresnel* f) {
    if (f->model || luts_.count(f)) return;
    gl::Texture lut = gl::create_texture(GL_TEXTURE_1D);
    std::vector<float> texels;
    for (const RGB& v : f->lut) texels.insert(texels.end(), {float(v.r), float(v.g), float(v.b)});
    glTextureStorage1D(lut.id(), 1, GL_RGB32F, static_cast<GLsizei>(f->lut.size()));
    glTextureSubImage1D(lut.id(), 0, 0, static_cast<GLsizei>(f->lut.size()), GL_RGB, GL_FLOAT, texels.data());
    glTextureParameteri(lut.id(), GL_TEXTURE_MIN_FILTER, GL_LINEAR);
    glTextureParameteri(lut.id(), GL_TEXTURE_MAG_FILTER, GL_LINEAR);
    glTextureParameteri(lut.id(), GL_TEXTURE_WRAP_S, GL_CLAMP_TO_EDGE);
    luts_.emplace(f, std::move(lut));
}

void GpuRenderer::set_fresnel(std::size_t sphere, const SphereFresnel* fresnel) {
    fresnel_.at(sphere) = fresnel;
    upload_lut(fresnel);
}

GLuint GpuRenderer::program(const std::string& kind, const std::vector<std::string>& defines, const std::string& fresnel_call) {
    std::string key = kind;
    for (const auto& d : defines) key += " " + d;
    if (auto it = programs_.find(key); it != programs_.end()) return it->second;

    std::string header = "#version 450 core\n";
    for (const auto& d : defines) header += define_line(d);
    if (!fresnel_call.empty()) header += "#define FRESNEL_CALL " + fresnel_call + "\n";
    std::string body = std::string(shader_text("environment.glsl"));
    if (kind == "capture") body += std::string(shader_text("cube_face.glsl")) + std::string(shader_text("capture.frag"));
    else if (kind == "downsample") body += std::string(shader_text("cube_face.glsl")) + std::string(shader_text("downsample.frag"));
    else if (kind == "prefilter") body += std::string(shader_text("cube_face.glsl")) + std::string(shader_text("prefilter.frag"));
    else if (kind == "background") body += std::string(shader_text("camera.glsl")) + std::string(shader_text("background.frag"));
    else {
        body += shader_text("reflection.glsl");
        for (const auto& d : defines)
            if (d.rfind("FRESNEL_MODEL ", 0) == 0) {
                const Model& model = find_model(d.substr(14));
                body += model.glsl_source();
            }
        if (kind == "sphere")
            body += std::string(shader_text("camera.glsl")) + std::string(shader_text("cube_face.glsl")) + std::string(shader_text("sphere.frag"));
        else body += shader_text("probe.comp");
    }
    // Linked once per context (another scene's renderer may have linked the same source); this scene's uniforms set
    // on its first use here.
    const GLuint id = kind == "probe" ? program_cache_->program({{GL_COMPUTE_SHADER, header + body}}, key)
                                      : program_cache_->program({fullscreen_vertex_stage(), {GL_FRAGMENT_SHADER, header + body}}, key);
    programs_.emplace(key, id);
    // What does not change while the renderer lives is set once here (uniforms a shader lacks are ignored).
    set_environment_uniforms(id);
    set_camera_uniforms(id);
    set(id, "u_env", 0);
    set(id, "u_equirect", 1);
    set(id, "u_fresnel_lut", 2);
    set(id, "u_prefiltered", 3);
    set(id, "u_dfg", 4);
    set(id, "u_area_radiance", 5);
    set(id, "u_area_position", 6);
    return id;
}

std::vector<std::string> GpuRenderer::compiled_variants() const {
    std::vector<std::string> keys;
    for (const auto& [key, _] : programs_) keys.push_back(key);
    return keys;
}

void GpuRenderer::set_environment_uniforms(GLuint p) const {
    const Environment& env = scene_.environment;
    set(p, "u_reference", env.reference());
    if (env.type == EnvironmentType::room) {
        const Room& room = env.room;
        set(p, "u_room_min", room.min);
        set(p, "u_room_max", room.max);
        set(p, "u_wall_x_min", room.wall_x_min);
        set(p, "u_wall_x_max", room.wall_x_max);
        set(p, "u_wall_z_min", room.wall_z_min);
        set(p, "u_wall_z_max", room.wall_z_max);
        set(p, "u_floor_light", room.floor_light);
        set(p, "u_floor_dark", room.floor_dark);
        set(p, "u_ceiling", room.ceiling);
        set(p, "u_checker", static_cast<float>(room.checker));
        const int panels = static_cast<int>(std::min<std::size_t>(room.panels.size(), 16));
        set(p, "u_panel_count", panels);
        for (int i = 0; i < panels; ++i) {
            const CeilingPanel& panel = room.panels[static_cast<std::size_t>(i)];
            const std::string index = "[" + std::to_string(i) + "]";
            glProgramUniform4f(p, glGetUniformLocation(p, ("u_panel_rect" + index).c_str()), float(panel.min_x),
                               float(panel.min_z), float(panel.max_x), float(panel.max_z));
            set(p, ("u_panel_radiance" + index).c_str(), panel.radiance);
        }
        const int boxes = static_cast<int>(std::min<std::size_t>(room.boxes.size(), 32));
        set(p, "u_box_count", boxes);
        for (int i = 0; i < boxes; ++i) {
            const RoomBox& box = room.boxes[static_cast<std::size_t>(i)];
            const std::string index = "[" + std::to_string(i) + "]";
            set(p, ("u_box_min" + index).c_str(), box.min);
            set(p, ("u_box_max" + index).c_str(), box.max);
            set(p, ("u_box_color" + index).c_str(), box.color);
        }
    } else if (env.type == EnvironmentType::sphere_room) {
        set(p, "u_sphere_room_radius", static_cast<float>(env.sphere_room.radius));
        set(p, "u_sphere_room_checker", static_cast<float>(env.sphere_room.checker_deg));
        set(p, "u_sphere_room_light", env.sphere_room.light);
        set(p, "u_sphere_room_dark", env.sphere_room.dark);
    } else {
        set(p, "u_equirect_intensity", static_cast<float>(env.equirect.intensity));
        if (env.equirect.proxy) {
            if (const auto* sphere = std::get_if<SphereProxy>(&*env.equirect.proxy)) {
                set(p, "u_proxy_radius", static_cast<float>(sphere->radius));
            } else {
                const auto& box = std::get<BoxProxy>(*env.equirect.proxy);
                set(p, "u_proxy_min", box.min - env.reference());
                set(p, "u_proxy_max", box.max - env.reference());
            }
        }
    }
    if (const auto box = env.parallax_box()) {  // the room's box or the equirect's box proxy
        set(p, "u_box_parallax_min", box->min - env.reference());
        set(p, "u_box_parallax_max", box->max - env.reference());
    }
}

void GpuRenderer::set_camera_uniforms(GLuint p) const {
    const CameraBasis basis = camera_basis(scene_.camera, scene_.width, scene_.height);
    set(p, "u_camera_position", basis.position);
    set(p, "u_camera_forward", basis.forward);
    set(p, "u_camera_right", basis.right);
    set(p, "u_camera_up", basis.up);
    glProgramUniform2f(p, glGetUniformLocation(p, "u_viewport"), float(scene_.width), float(scene_.height));
}

EnvironmentCube::Descriptor GpuRenderer::cube_descriptor() const {
    return {scene_.environment.cube_size, features_.distance_channel, features_.prefiltered_map};
}

void GpuRenderer::capture_environment() {
    if (!features_.environment_capture) return;
    if (!own_cube_) own_cube_ = EnvironmentCube::create(cube_descriptor());
    capture_environment(*own_cube_);
    if (features_.prefiltered_map) {
        const int size = PrefilteredCube::size_for(scene_.environment.cube_size);
        if (!own_prefiltered_) own_prefiltered_ = PrefilteredCube::create({size, PrefilteredCube::levels_for(size)});
        prefilter(*own_cube_, *own_prefiltered_);
    }
    for (int m : features_.downsample_sizes) {
        auto it = own_downsampled_.find(m);
        if (it == own_downsampled_.end()) it = own_downsampled_.emplace(m, DownsampledCube::create({m})).first;
        downsample(*own_cube_, it->second);
    }
}

void GpuRenderer::downsample(const EnvironmentCube& source, const DownsampledCube& target) {
    const GLuint p = program("downsample", {});
    set(p, "u_source_size", source.size);
    set(p, "u_m", target.m);
    const gl::Framebuffer fbo = gl::create_framebuffer();
    glNamedFramebufferTexture(fbo.id(), GL_COLOR_ATTACHMENT0, target.radiance.id(), 0);
    glNamedFramebufferTexture(fbo.id(), GL_COLOR_ATTACHMENT1, target.position.id(), 0);
    const GLenum buffers[2] = {GL_COLOR_ATTACHMENT0, GL_COLOR_ATTACHMENT1};
    glNamedFramebufferDrawBuffers(fbo.id(), 2, buffers);
    if (glCheckNamedFramebufferStatus(fbo.id(), GL_FRAMEBUFFER) != GL_FRAMEBUFFER_COMPLETE)
        throw GlError("the downsampled cube cannot be rendered to");
    glBindFramebuffer(GL_FRAMEBUFFER, fbo.id());
    glUseProgram(p);
    glBindVertexArray(vao_.id());
    glDisable(GL_DEPTH_TEST);
    glBindTextureUnit(0, source.texture.id());
    glViewport(0, 0, 6 * target.m, target.m);
    glDrawArrays(GL_TRIANGLES, 0, 3);
    glBindFramebuffer(GL_FRAMEBUFFER, 0);
    check_gl("downsampling the environment");
    downsampled_[target.m] = &target;
}

void GpuRenderer::prefilter(const EnvironmentCube& source, const PrefilteredCube& target) {
    const GLuint p = program("prefilter", {});
    set(p, "u_source_size", source.size);
    set(p, "u_samples", 64);
    const gl::Framebuffer fbo = gl::create_framebuffer();
    glUseProgram(p);
    glBindVertexArray(vao_.id());
    glDisable(GL_DEPTH_TEST);
    glBindTextureUnit(0, source.texture.id());
    for (int level = 0; level < target.levels; ++level) {
        const int n = std::max(1, target.size >> level);
        set(p, "u_size", n);
        set(p, "u_roughness", target.levels > 1 ? float(level) / float(target.levels - 1) : 0.0f);
        glViewport(0, 0, n, n);
        for (int face = 0; face < 6; ++face) {
            glNamedFramebufferTextureLayer(fbo.id(), GL_COLOR_ATTACHMENT0, target.texture.id(), level, face);
            if (glCheckNamedFramebufferStatus(fbo.id(), GL_FRAMEBUFFER) != GL_FRAMEBUFFER_COMPLETE)
                throw GlError("prefiltered cube face " + std::to_string(face) + " level " + std::to_string(level) + " cannot be rendered to");
            glBindFramebuffer(GL_FRAMEBUFFER, fbo.id());
            set(p, "u_face", face);
            glDrawArrays(GL_TRIANGLES, 0, 3);
        }
    }
    glBindFramebuffer(GL_FRAMEBUFFER, 0);
    check_gl("prefiltering the environment");
    prefiltered_ = &target;
}

void GpuRenderer::use_dfg(const DfgSet& set) {
    for (const auto& [fresnel, table] : set.tables) upload_dfg(fresnel, table);
}

void GpuRenderer::upload_dfg(const SphereFresnel* fresnel, const DfgTable& table) {
    if (dfg_.count(fresnel)) return;
    gl::Texture texture = gl::create_texture(GL_TEXTURE_2D);
    std::vector<float> texels;
    for (const RGB& v : table.values) texels.insert(texels.end(), {float(v.r), float(v.g), float(v.b)});
    glTextureStorage2D(texture.id(), 1, GL_RGB32F, DfgTable::kMuSize, DfgTable::kRoughnessSize);
    glTextureSubImage2D(texture.id(), 0, 0, 0, DfgTable::kMuSize, DfgTable::kRoughnessSize, GL_RGB, GL_FLOAT, texels.data());
    glTextureParameteri(texture.id(), GL_TEXTURE_MIN_FILTER, GL_LINEAR);
    glTextureParameteri(texture.id(), GL_TEXTURE_MAG_FILTER, GL_LINEAR);
    glTextureParameteri(texture.id(), GL_TEXTURE_WRAP_S, GL_CLAMP_TO_EDGE);
    glTextureParameteri(texture.id(), GL_TEXTURE_WRAP_T, GL_CLAMP_TO_EDGE);
    check_gl("uploading a DFG table");
    dfg_.emplace(fresnel, std::move(texture));
}

void GpuRenderer::capture_environment(const EnvironmentCube& cube) {
    const int n = cube.size;
    const GLuint p = program("capture", {environment_define(scene_.environment)});
    set(p, "u_size", n);
    const gl::Framebuffer fbo = gl::create_framebuffer();
    if (scene_.environment.type == EnvironmentType::equirect) {  // an equirect on its proxy: the image is painted on it
        if (!equirect_) throw std::invalid_argument("GpuRenderer: the equirect image is missing");
        glBindTextureUnit(1, equirect_->id());
    }
    glUseProgram(p);
    glBindVertexArray(vao_.id());
    glDisable(GL_DEPTH_TEST);
    glViewport(0, 0, n, n);
    for (int face = 0; face < 6; ++face) {
        glNamedFramebufferTextureLayer(fbo.id(), GL_COLOR_ATTACHMENT0, cube.texture.id(), 0, face);
        if (glCheckNamedFramebufferStatus(fbo.id(), GL_FRAMEBUFFER) != GL_FRAMEBUFFER_COMPLETE)
            throw GlError("cube-map face " + std::to_string(face) + " cannot be rendered to");
        glBindFramebuffer(GL_FRAMEBUFFER, fbo.id());
        set(p, "u_face", face);
        glDrawArrays(GL_TRIANGLES, 0, 3);
    }
    glBindFramebuffer(GL_FRAMEBUFFER, 0);
    if (cube.levels > 1) glGenerateTextureMipmap(cube.texture.id());
    check_gl("capturing the environment");
    cube_ = &cube;
}

void GpuRenderer::draw_frame(bool diagnostics) {
    glBindFramebuffer(GL_FRAMEBUFFER, framebuffer_.id());
    glViewport(0, 0, scene_.width, scene_.height);
    glBindVertexArray(vao_.id());
    const float clear_depth = 1.0f;
    glClearNamedFramebufferfv(framebuffer_.id(), GL_DEPTH, 0, &clear_depth);
    if (cube_) glBindTextureUnit(0, cube_->texture.id());
    if (scene_.environment.type == EnvironmentType::equirect) {
        if (!equirect_) throw std::invalid_argument("GpuRenderer: the equirect image is missing");
        glBindTextureUnit(1, equirect_->id());
    }

    glDisable(GL_DEPTH_TEST);
    glDepthMask(GL_FALSE);
    if (diagnostics) {
        const float zero[4] = {0, 0, 0, 0};
        glClearNamedFramebufferfv(framebuffer_.id(), GL_COLOR, 0, zero);
    } else {
        glUseProgram(program("background", {environment_define(scene_.environment)}));
        glDrawArrays(GL_TRIANGLES, 0, 3);
    }

    glEnable(GL_DEPTH_TEST);
    glDepthFunc(GL_LESS);
    glDepthMask(GL_TRUE);
    for (std::size_t i = 0; i < scene_.spheres.size(); ++i) {
        const Sphere& sphere = scene_.spheres[i];
        const SphereFresnel& fresnel = *fresnel_[i];
        std::vector<std::string> defines = sphere_defines(scene_, sphere);
        if (diagnostics) defines.push_back("LOCALIZATION_DIAGNOSTICS");
        const GLuint p = program("sphere", defines, fresnel.model ? model_call(*fresnel.model) : "");
        set(p, "u_sphere_center", sphere.center);
        set(p, "u_sphere_radius", static_cast<float>(sphere.radius));
        if (sphere.rough() && sphere.glossy == GlossyMethod::localized) {
            const auto it = downsampled_.find(sphere.localized_size);
            if (it == downsampled_.end()) throw std::logic_error("GpuRenderer: a localized sphere needs its downsampled cube");
            set(p, "u_roughness", static_cast<float>(sphere.roughness));
            glBindTextureUnit(5, it->second->radiance.id());
            glBindTextureUnit(6, it->second->position.id());
        } else if (sphere.rough()) {
            if (!prefiltered_) throw std::logic_error("GpuRenderer: a rough sphere needs the prefiltered cube");
            if (!dfg_.count(&fresnel)) upload_dfg(&fresnel, make_dfg_table(fresnel));
            set(p, "u_roughness", static_cast<float>(sphere.roughness));
            set(p, "u_prefiltered_levels", static_cast<float>(prefiltered_->levels));
            glBindTextureUnit(3, prefiltered_->texture.id());
            glBindTextureUnit(4, dfg_.at(&fresnel).id());
        }
        if (fresnel.model) {
            set_model_parameters(p, *fresnel.model, fresnel.parameters);
        } else {
            upload_lut(&fresnel);
            glBindTextureUnit(2, luts_.at(&fresnel).id());
        }
        glUseProgram(p);
        glDrawArrays(GL_TRIANGLES, 0, 3);
    }
    glBindFramebuffer(GL_FRAMEBUFFER, 0);
}

Image GpuRenderer::render() {
    draw_frame();
    return read_frame();
}

Image GpuRenderer::render_localization() {
    draw_frame(true);
    return read_frame();
}

Image GpuRenderer::read_frame() const {
    std::vector<float> rgba(static_cast<std::size_t>(scene_.width) * scene_.height * 4);
    glGetTextureImage(color_.id(), 0, GL_RGBA, GL_FLOAT, static_cast<GLsizei>(rgba.size() * sizeof(float)), rgba.data());
    check_gl("reading a frame back");
    Image image(scene_.width, scene_.height);
    for (int y = 0; y < scene_.height; ++y)
        for (int x = 0; x < scene_.width; ++x) {
            const float* v = &rgba[4 * (static_cast<std::size_t>(y) * scene_.width + x)];
            image.set(x, scene_.height - 1 - y, {v[0], v[1], v[2]});
        }
    return image;
}

std::vector<double> GpuRenderer::time_frames(int frames) {
    std::vector<double> ms;
    draw_frame();  // compiles every variant before timing
    glFinish();
    for (int i = 0; i < frames; ++i) ms.push_back(finished_ms([&] { draw_frame(); }));
    check_gl("timing frames");
    return ms;
}

std::vector<ProbeResult> GpuRenderer::probe(const Sphere& settings, std::span<const std::array<Vec3, 2>> rays) {
    if (!cube_) throw std::logic_error("GpuRenderer::probe: no captured cube map");
    std::vector<std::string> defines;
    for (const auto& d : sphere_defines(scene_, settings))
        if (d.rfind("FRESNEL", 0) != 0 && d.rfind("GLOSSY", 0) != 0) defines.push_back(d);
    const GLuint p = program("probe", defines);
    const int count = static_cast<int>(rays.size());
    set(p, "u_count", count);
    std::vector<float> input;
    for (const auto& [x, r] : rays) input.insert(input.end(), {float(x.x), float(x.y), float(x.z), 0.f, float(r.x), float(r.y), float(r.z), 0.f});
    const gl::Buffer input_buffer = gl::create_buffer(), output_buffer = gl::create_buffer();
    const GLuint buffers[2] = {input_buffer.id(), output_buffer.id()};
    glNamedBufferStorage(buffers[0], static_cast<GLsizeiptr>(input.size() * sizeof(float)), input.data(), 0);
    glNamedBufferStorage(buffers[1], static_cast<GLsizeiptr>(input.size() * sizeof(float)), nullptr, GL_MAP_READ_BIT);
    glBindBufferBase(GL_SHADER_STORAGE_BUFFER, 0, buffers[0]);
    glBindBufferBase(GL_SHADER_STORAGE_BUFFER, 1, buffers[1]);
    glBindTextureUnit(0, cube_->texture.id());
    glUseProgram(p);
    glDispatchCompute(static_cast<GLuint>((count + 63) / 64), 1, 1);
    glMemoryBarrier(GL_BUFFER_UPDATE_BARRIER_BIT);
    std::vector<float> output(input.size());
    glGetNamedBufferSubData(buffers[1], 0, static_cast<GLsizeiptr>(output.size() * sizeof(float)), output.data());
    check_gl("probing reflection lookups");
    std::vector<ProbeResult> results;
    for (int i = 0; i < count; ++i) {
        const float* v = &output[8 * static_cast<std::size_t>(i)];
        results.push_back({{v[0], v[1], v[2]}, {v[4], v[5], v[6], v[7]}});
    }
    return results;
}

std::vector<float> GpuRenderer::read_cube_face(int face) const {
    const int n = scene_.environment.cube_size;
    std::vector<float> texels(static_cast<std::size_t>(n) * n * 4);
    glGetTextureSubImage(cube_->texture.id(), 0, 0, 0, face, n, n, 1, GL_RGBA, GL_FLOAT, static_cast<GLsizei>(texels.size() * sizeof(float)),
                         texels.data());
    check_gl("reading a cube face");
    return texels;
}

}  // namespace metalfit::glpreview
