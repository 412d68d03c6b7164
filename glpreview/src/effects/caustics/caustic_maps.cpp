#include "caustic_maps.hpp"

#include <algorithm>
#include <cmath>
#include <numbers>

#include "../lights/light.hpp"
#include "../rings/ring.hpp"
#include "glpreview/effects/effect.hpp"
#include "glpreview/effects/reflection_lookup.hpp"
#include "glpreview/gl/program_cache.hpp"
#include "glpreview/gl/saved_gl_state.hpp"
#include "glpreview/gl/uniforms.hpp"
#include "glpreview/render/gpu_renderer.hpp"
#include "glpreview/render/gpu_resources.hpp"
#include "glpreview/render/sphere_shader.hpp"
#include "render/embedded_shaders.hpp"

namespace metalfit::glpreview {
namespace {

bool in_spot_cone(const Light& light, const BoundingSphere& b) {
    const Vec3 to = b.centre - light.position;
    const double distance = length(to);
    if (distance <= b.radius) return true;
    const double to_radians = std::numbers::pi / 180;
    const double angle = std::acos(std::clamp(dot(to, light.direction) / distance, -1.0, 1.0));
    return angle - std::asin(b.radius / distance) < light.cone_outer_deg * to_radians;
}

// The splat's program: a vertex and a fragment stage of their own (points), linked once per renderer.
struct SplatProgram {
    ProgramCache cache;
};

struct CausticsInProgress {
    bool active = false;
    struct Scope {  // active while it lives
        explicit Scope(CausticsInProgress& state) : state_(state) { state_.active = true; }
        ~Scope() { state_.active = false; }
        CausticsInProgress& state_;
    };
};

// The room's distance cube without the rings (what a photon leaving a ring lands on), made once per renderer.
struct RoomDistances {
    std::optional<EnvironmentCube> cube;
};

void draw_fullscreen_into(GLuint fbo, GLuint texture, int layer) {
    if (layer >= 0)
        glNamedFramebufferTextureLayer(fbo, GL_COLOR_ATTACHMENT0, texture, 0, layer);
    else
        glNamedFramebufferTexture(fbo, GL_COLOR_ATTACHMENT0, texture, 0);
    if (glCheckNamedFramebufferStatus(fbo, GL_FRAMEBUFFER) != GL_FRAMEBUFFER_COMPLETE)
        throw GlError("a caustics target cannot be rendered to");
    glBindFramebuffer(GL_FRAMEBUFFER, fbo);
    glDrawArrays(GL_TRIANGLES, 0, 3);
}

const EnvironmentCube& room_distances(GpuRenderer& renderer) {
    auto& state = renderer.frame().state<RoomDistances>();
    if (state.cube) return *state.cube;
    const int size = std::min(renderer.scene().environment.cube_size, 256);
    state.cube = EnvironmentCube::create({size, true, false});
    ShaderBuilder builder("caustic-room-distance");
    declare_environment(renderer.scene(), builder);
    builder.define("ROOM_ONLY").source(shader_text("cube_face.glsl")).source(shader_text("room_distance.frag"));
    const BuiltProgram& p = renderer.program(builder);
    set_uniform(p.id(), "u_size", size);
    glUseProgram(p.id());
    glViewport(0, 0, size, size);
    const gl::Framebuffer fbo = gl::create_framebuffer();
    for (int face = 0; face < 6; ++face) {
        set_uniform(p.id(), "u_face", face);
        draw_fullscreen_into(fbo.id(), state.cube->texture.id(), face);
    }
    check_gl("capturing the caustics' room distances");
    return *state.cube;
}

}  // namespace

bool making_caustics(GpuRenderer& renderer) { return renderer.frame().state<CausticsInProgress>().active; }

CausticSettings caustic_settings(const Scene& scene) {
    const CausticSettings* settings = scene.effects.find<CausticSettings>();
    return settings ? *settings : CausticSettings{};
}

CausticPlan plan_caustics(const Scene& scene) {
    CausticPlan plan;
    const Rings* rings = scene.effects.find<Rings>();
    const Lights* lights = scene.effects.find<Lights>();
    if (!rings || rings->rings.empty()) {
        plan.why = "no ring (a mirror that can focus light)";
        return plan;
    }
    if (scene.environment.type != EnvironmentType::room) {
        plan.why = "no room to receive the light";
        return plan;
    }
    if (!lights || lights->lights.empty()) {
        plan.why = "no light";
        return plan;
    }
    std::vector<std::string> reasons;
    for (std::size_t l = 0; l < lights->lights.size(); ++l) {
        const Light& light = lights->lights[l];
        const std::string name = "light " + std::to_string(l) + " (" + to_string(light.type) + ")";
        if (light.type == LightType::sphere) {
            reasons.push_back(name + ": sphere lights throw no caustic here");
            continue;
        }
        std::size_t rings_lit = 0;
        for (std::size_t r = 0; r < rings->rings.size(); ++r) {
            if (light.type == LightType::spot && !in_spot_cone(light, rings->rings[r].bounds())) continue;
            plan.jobs.push_back({l, r});
            ++rings_lit;
        }
        reasons.push_back(name + ": " + (rings_lit ? std::to_string(rings_lit) + " ring(s)" : "no ring in its cone"));
    }
    std::string why;
    for (const std::string& r : reasons) why += (why.empty() ? "" : "; ") + r;
    plan.why = why;
    return plan;
}

void render_caustic_light_maps(GpuRenderer& renderer, const CausticPlan& plan, const CausticSettings& settings,
                               const RoomLightMaps& maps) {
    const SavedGlState saved;
    const CausticsInProgress::Scope in_progress(renderer.frame().state<CausticsInProgress>());

    const Scene& scene = renderer.scene();
    const Room& room = scene.environment.room;
    const Rings& rings = *scene.effects.find<Rings>();
    const Lights& lights = *scene.effects.find<Lights>();
    const float zero[4] = {0, 0, 0, 0};
    glClearTexImage(maps.texture.id(), 0, GL_RGBA, GL_FLOAT, zero);
    glDisable(GL_DEPTH_TEST);
    glBindVertexArray(renderer.vertex_array());
    const EnvironmentCube& distances = room_distances(renderer);

    // The caustic map's program: the environment (the rings, their Fresnel), the safeguarded impostor search.
    ShaderBuilder builder("caustic-map");
    declare_environment(scene, builder);
    declare_reflection_lookup(Sphere{}, builder);
    builder.source(shader_text("caustic_map.frag"));
    const BuiltProgram& map_program = renderer.program(builder);
    const GLuint mp = map_program.id();
    set_uniform(mp, "u_map_size", settings.map_size);
    set_uniform(mp, "u_room_min_c", room.min);
    set_uniform(mp, "u_room_max_c", room.max);
    const int spheres = static_cast<int>(std::min<std::size_t>(scene.spheres.size(), 256));
    set_uniform(mp, "u_caustic_sphere_count", spheres);
    for (int i = 0; i < spheres; ++i) {
        const Sphere& s = scene.spheres[static_cast<std::size_t>(i)];
        glProgramUniform4f(mp, glGetUniformLocation(mp, ("u_caustic_spheres[" + std::to_string(i) + "]").c_str()),
                           float(s.center.x), float(s.center.y), float(s.center.z), float(s.radius));
    }

    const int n = settings.map_size;
    const gl::Texture hits = gl::create_texture(GL_TEXTURE_2D), power = gl::create_texture(GL_TEXTURE_2D);
    glTextureStorage2D(hits.id(), 1, GL_RGBA32F, n, n);
    glTextureStorage2D(power.id(), 1, GL_RGBA32F, n, n);
    const gl::Framebuffer map_fbo = gl::create_framebuffer();
    glNamedFramebufferTexture(map_fbo.id(), GL_COLOR_ATTACHMENT0, hits.id(), 0);
    glNamedFramebufferTexture(map_fbo.id(), GL_COLOR_ATTACHMENT1, power.id(), 0);
    const GLenum buffers[2] = {GL_COLOR_ATTACHMENT0, GL_COLOR_ATTACHMENT1};
    glNamedFramebufferDrawBuffers(map_fbo.id(), 2, buffers);
    if (glCheckNamedFramebufferStatus(map_fbo.id(), GL_FRAMEBUFFER) != GL_FRAMEBUFFER_COMPLETE)
        throw GlError("the caustic map cannot be rendered to");

    auto& splat = renderer.frame().state<SplatProgram>();
    const GLuint sp = splat.cache.program({{GL_VERTEX_SHADER, std::string(shader_text("caustic_splat.vert"))},
                                           {GL_FRAGMENT_SHADER, std::string(shader_text("caustic_splat.frag"))}},
                                          "caustic-splat");
    GLfloat point_range[2] = {1, 1};
    glGetFloatv(GL_POINT_SIZE_RANGE, point_range);
    set_uniform(sp, "u_map_size", n);
    set_uniform(sp, "u_sigma", static_cast<float>(settings.filter_width));
    set_uniform(sp, "u_max_point_size", point_range[1]);
    glProgramUniform1i(sp, glGetUniformLocation(sp, "u_caustic_hits"), 0);
    glProgramUniform1i(sp, glGetUniformLocation(sp, "u_caustic_power"), 1);
    const gl::Framebuffer splat_fbo = gl::create_framebuffer();

    const double to_radians = std::numbers::pi / 180;
    for (const CausticJob& job : plan.jobs) {
        const Light& light = lights.lights[job.light];
        const BoundingSphere bounds = rings.rings[job.ring].bounds();
        set_uniform(mp, "u_ring", static_cast<int>(job.ring));
        set_uniform(mp, "u_caustic_power_in", light.power());
        set_uniform(mp, "u_caustic_direction", light.direction);
        if (!light.local()) {  // a parallel beam just wide enough for the ring's bounding sphere
            const Vec3 d = light.direction;
            const Vec3 helper = std::abs(d.y) < 0.99 ? Vec3{0, 1, 0} : Vec3{1, 0, 0};
            const Vec3 a = normalize(cross(helper, d)), b = cross(d, a);
            const double r = bounds.radius * 1.001;
            set_uniform(mp, "u_caustic_kind", 0);
            set_uniform(mp, "u_beam_origin", bounds.centre - (r + 0.01) * d - r * a - r * b);
            set_uniform(mp, "u_beam_u", 2 * r * a);
            set_uniform(mp, "u_beam_v", 2 * r * b);
        } else {  // the cap of directions that holds the ring's bounding sphere (or a spot's cone, if narrower)
            const Vec3 to = bounds.centre - light.position;
            const double distance = length(to);
            Vec3 axis = normalize(to);
            double cap_cos =
                distance > bounds.radius * 1.001 ? std::sqrt(1 - std::pow(bounds.radius * 1.001 / distance, 2)) : -1.0;
            float cone_outer = -2, cone_inner = -1;
            if (light.type == LightType::spot) {
                const double cos_outer = std::cos(light.cone_outer_deg * to_radians);
                if (cos_outer > cap_cos) {
                    cap_cos = cos_outer;
                    axis = light.direction;
                }
                cone_outer = static_cast<float>(cos_outer);
                cone_inner = static_cast<float>(
                    std::max(std::cos(light.cone_inner_deg * to_radians), cos_outer + 1e-6));  // as spot_weight
            }
            set_uniform(mp, "u_caustic_kind", 1);
            set_uniform(mp, "u_caustic_position", light.position);
            set_uniform(mp, "u_cap_axis", axis);
            set_uniform(mp, "u_cap_cos", static_cast<float>(cap_cos));
            glProgramUniform2f(mp, glGetUniformLocation(mp, "u_spot_cone"), cone_outer, cone_inner);
        }
        renderer.bind_environment(map_program);  // the rings' Fresnel (the splat below takes units of its own)
        map_program.bind("u_env", distances.texture.id());
        glUseProgram(mp);
        glDisable(GL_BLEND);
        glViewport(0, 0, n, n);
        glBindFramebuffer(GL_FRAMEBUFFER, map_fbo.id());
        glDrawArrays(GL_TRIANGLES, 0, 3);

        // The splat: every photon as a point into each face's light map, added.
        glUseProgram(sp);
        glBindTextureUnit(0, hits.id());
        glBindTextureUnit(1, power.id());
        glEnable(GL_PROGRAM_POINT_SIZE);
        glEnable(GL_BLEND);
        glBlendEquation(GL_FUNC_ADD);
        glBlendFunc(GL_ONE, GL_ONE);
        glViewport(0, 0, maps.size, maps.size);
        for (int face = 0; face < 6; ++face) {
            const RoomFace f = room_face(room, face);
            set_uniform(sp, "u_face", face);
            set_uniform(sp, "u_face_origin", f.origin);
            set_uniform(sp, "u_face_u", f.u);
            set_uniform(sp, "u_face_v", f.v);
            glProgramUniform2f(sp, glGetUniformLocation(sp, "u_texel_metres"), float(length(f.u) / maps.size),
                               float(length(f.v) / maps.size));
            glNamedFramebufferTextureLayer(splat_fbo.id(), GL_COLOR_ATTACHMENT0, maps.texture.id(), 0, face);
            if (glCheckNamedFramebufferStatus(splat_fbo.id(), GL_FRAMEBUFFER) != GL_FRAMEBUFFER_COMPLETE)
                throw GlError("a caustic light map cannot be rendered to");
            glBindFramebuffer(GL_FRAMEBUFFER, splat_fbo.id());
            glDrawArrays(GL_POINTS, 0, n * n);
        }
        glDisable(GL_PROGRAM_POINT_SIZE);
    }
    check_gl("rendering the caustic maps");
}

}  // namespace metalfit::glpreview
