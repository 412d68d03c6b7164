#include "rings_effect.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <numbers>
#include <stdexcept>

#include "glpreview/gl/objects.hpp"
#include "glpreview/gl/uniforms.hpp"
#include "glpreview/render/gpu_renderer.hpp"
#include "glpreview/render/sphere_fresnel.hpp"
#include "render/embedded_shaders.hpp"
#include "ring.hpp"

namespace metalfit::glpreview {
namespace {

const Rings* rings_of(const Scene& scene) {
    const Rings* rings = scene.effects.find<Rings>();
    return rings && !rings->rings.empty() ? rings : nullptr;
}

// Shadow rays start this far from their surface (cpu_lights' epsilon).
constexpr double kRingShadowEpsilon = 1e-6;

// Entries of a ring's Fresnel table on the GPU (μ_k = k / (n − 1)): the reference's own table, a model tabulated.
constexpr int kRingFresnelSize = kReferenceLutSize;

// The rings' Fresnel tables, one row per ring (the renderer's, on its blackboard).
struct RingFresnelTexture {
    gl::Texture texture;
};

GLuint ring_fresnel_texture(GpuRenderer& renderer, const Rings& rings) {
    auto& state = renderer.frame().state<RingFresnelTexture>();
    if (state.texture.id() != 0) return state.texture.id();
    if (rings.fresnel.size() != rings.rings.size())
        throw std::logic_error("rings: their Fresnel is not resolved (resolve_effect_materials)");
    std::vector<float> texels;
    for (const SphereFresnel* fresnel : rings.fresnel)
        for (int k = 0; k < kRingFresnelSize; ++k) {
            const RGB f = (*fresnel)(static_cast<double>(k) / (kRingFresnelSize - 1));
            texels.insert(texels.end(), {float(f.r), float(f.g), float(f.b)});
        }
    gl::Texture texture = gl::create_texture(GL_TEXTURE_2D);
    const auto rows = static_cast<GLsizei>(rings.rings.size());
    glTextureStorage2D(texture.id(), 1, GL_RGB32F, kRingFresnelSize, rows);
    glTextureSubImage2D(texture.id(), 0, 0, 0, kRingFresnelSize, rows, GL_RGB, GL_FLOAT, texels.data());
    glTextureParameteri(texture.id(), GL_TEXTURE_MIN_FILTER, GL_LINEAR);
    glTextureParameteri(texture.id(), GL_TEXTURE_MAG_FILTER, GL_LINEAR);
    glTextureParameteri(texture.id(), GL_TEXTURE_WRAP_S, GL_CLAMP_TO_EDGE);
    glTextureParameteri(texture.id(), GL_TEXTURE_WRAP_T, GL_CLAMP_TO_EDGE);
    check_gl("uploading the rings' Fresnel");
    state.texture = std::move(texture);
    return state.texture.id();
}

class RingsEffect final : public Effect {
public:
    std::string_view name() const override { return "rings"; }

    std::vector<const char*> scene_keys() const override { return {"rings"}; }
    void read_scene(const SceneReader& top, Scene& scene) const override {
        if (top.has("rings")) scene.effects.set(read_rings(top));
    }
    void check_scene(const SceneReader& top, const Scene& scene) const override {
        if (const Rings* rings = rings_of(scene)) check_rings(top, scene, *rings);
    }

    std::vector<BoundingSphere> shadow_casters(const Scene& scene) const override {
        std::vector<BoundingSphere> bounds;
        if (const Rings* rings = rings_of(scene))
            for (const Ring& ring : rings->rings) bounds.push_back(ring.bounds());
        return bounds;
    }

    void resolve_materials(Scene& scene, FresnelLibrary& library) const override {
        const Rings* rings = rings_of(scene);
        if (!rings) return;
        Rings resolved = *rings;
        resolved.fresnel.clear();
        for (std::size_t i = 0; i < resolved.rings.size(); ++i)
            resolved.fresnel.push_back(&library.get(resolved.rings[i].surface(), "rings[" + std::to_string(i) + "]"));
        scene.effects.set(std::move(resolved));
    }

    // The CPU references: a ray meeting a wall before the room sees F(μ) × the room along the reflected ray (one
    // reflection, the room alone), as rings_seen in ring.glsl; shadow rays stop at the first wall (rings_distance).
    bool lights_cpu_reference(const Scene& scene) const override { return rings_of(scene) != nullptr; }
    std::optional<EnvironmentHit> cpu_environment_object(const Scene& scene, Vec3 o, Vec3 d, double t_max,
                                                         const EnvironmentTracer& room) const override {
        const Rings* rings = rings_of(scene);
        if (!rings) return std::nullopt;
        const std::optional<RingHit> hit = intersect_rings(rings->rings, o, d, 0, t_max);
        if (!hit) return std::nullopt;
        if (rings->fresnel.size() != rings->rings.size())
            throw std::logic_error("rings: their Fresnel is not resolved (resolve_effect_materials)");
        const double mu = std::clamp(-dot(d, hit->normal), 0.0, 1.0);
        const Vec3 reflected = d - 2 * dot(d, hit->normal) * hit->normal;
        return EnvironmentHit{(*rings->fresnel[hit->ring])(mu)*room.room_trace(hit->point, reflected).radiance, hit->t};
    }
    double cpu_occluder(const Scene& scene, Vec3 o, Vec3 d) const override {
        const Rings* rings = rings_of(scene);
        if (!rings) return std::numeric_limits<double>::infinity();
        const std::optional<RingHit> hit =
            intersect_rings(rings->rings, o, d, kRingShadowEpsilon, std::numeric_limits<double>::infinity());
        return hit ? hit->t : std::numeric_limits<double>::infinity();
    }

    void declare_environment_program(const Scene& scene, ShaderBuilder& builder) const override {
        if (!rings_of(scene)) return;
        builder.define("ENVIRONMENT_OBJECT", "rings_seen")
            .define("ENVIRONMENT_OCCLUDER", "rings_distance")
            .source(shader_text("ring.glsl"))
            .sampler("u_ring_fresnel");
    }

    void set_program_uniforms(const Scene& scene, GLuint p) const override {
        const Rings* rings = rings_of(scene);
        if (!rings) return;
        set_uniform(p, "u_ring_count", static_cast<int>(rings->rings.size()));
        const double to_radians = std::numbers::pi / 180;
        for (std::size_t i = 0; i < rings->rings.size(); ++i) {
            const Ring& ring = rings->rings[i];
            const auto name = [i](const char* array) { return std::string(array) + "[" + std::to_string(i) + "]"; };
            set_uniform(p, name("u_ring_base").c_str(), ring.base);
            glProgramUniform4f(p, glGetUniformLocation(p, name("u_ring_shape").c_str()), float(ring.radius),
                               float(ring.height), float(std::cos(ring.facing_deg * to_radians)),
                               float(std::sin(ring.facing_deg * to_radians)));
            set_uniform(p, name("u_ring_cos_half_arc").c_str(),
                        ring.arc_deg >= 360 ? -2.0f : static_cast<float>(std::cos(0.5 * ring.arc_deg * to_radians)));
        }
    }

    void bind_environment_program(GpuRenderer& renderer, const BuiltProgram& program) const override {
        const Rings* rings = rings_of(renderer.scene());
        if (!rings || !program.reads("u_ring_fresnel")) return;
        program.bind("u_ring_fresnel", ring_fresnel_texture(renderer, *rings));
    }
};

}  // namespace

const Effect& rings_effect() {
    static const RingsEffect effect;
    return effect;
}

}  // namespace metalfit::glpreview
