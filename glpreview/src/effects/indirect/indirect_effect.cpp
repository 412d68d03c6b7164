#include "indirect_effect.hpp"

#include <algorithm>
#include <cmath>
#include <cstring>
#include <numbers>
#include <random>

#include "../lights/light.hpp"
#include "../rings/ring.hpp"
#include "glpreview/effects/registry.hpp"
#include "glpreview/gl/uniforms.hpp"
#include "glpreview/render/environment.hpp"
#include "glpreview/render/frame_inputs.hpp"
#include "glpreview/render/gpu_renderer.hpp"
#include "glpreview/render/preview_passes.hpp"
#include "glpreview/render/sphere_intersection.hpp"
#include "indirect_light_maps.hpp"
#include "indirect_settings.hpp"
#include "render/embedded_shaders.hpp"
#include "virtual_lights.hpp"

#include <optional>

namespace metalfit::glpreview {
namespace {

using graph::Builder;
using graph::Handle;
using graph::Out;
using graph::Processor;
using graph::Resources;

// The virtual lights of a scene, as the graph hands them on.
struct VirtualLightSet {
    std::vector<VirtualLight> lights;
};

// Why the scene gets no indirect light, or "" when it does.
std::string why_not(const Scene& scene) {
    if (!scene.effects.find<IndirectSettings>()) return "the scene asks for no 'indirect'";
    if (scene.environment.type != EnvironmentType::room) return "no room";
    const Lights* lights = scene.effects.find<Lights>();
    if (!lights || std::none_of(lights->lights.begin(), lights->lights.end(),
                                [](const Light& l) { return l.type != LightType::sphere; }))
        return "no point, spot or directional light to shoot paths from";
    return "";
}
bool asked(const Scene& scene) { return why_not(scene).empty(); }

// The light maps the renderer made itself (no graph: tests, benchmarks).
struct OwnIndirectMaps {
    std::optional<RoomLightMaps> maps;
};

// A cosine-weighted direction about n from two numbers in [0, 1).
Vec3 cosine_direction(Vec3 n, double u1, double u2) {
    const Vec3 a = normalize(std::abs(n.y) < 0.99 ? cross(n, Vec3{0, 1, 0}) : cross(n, Vec3{1, 0, 0}));
    const Vec3 b = cross(n, a);
    const double r = std::sqrt(u1), phi = 2 * std::numbers::pi * u2;
    return normalize(r * std::cos(phi) * a + r * std::sin(phi) * b + std::sqrt(std::max(0.0, 1 - u1)) * n);
}

// The floor points the figures are taken at: a grid of 24 × 24 cell centres.
std::vector<Vec3> floor_points(const Room& room) {
    std::vector<Vec3> points;
    constexpr int kSide = 24;
    for (int i = 0; i < kSide; ++i)
        for (int j = 0; j < kSide; ++j)
            points.push_back({room.min.x + (i + 0.5) / kSide * (room.max.x - room.min.x), room.min.y,
                              room.min.z + (j + 0.5) / kSide * (room.max.z - room.min.z)});
    return points;
}

double mean(const RGB& c) { return (c.r + c.g + c.b) / 3; }

// The figures of metrics.json's "indirect" (see add_output_passes), with a white floor (albedo 1).
Json indirect_figures(const Scene& scene, const Effect& effect) {
    const IndirectSettings& settings = *scene.effects.find<IndirectSettings>();
    const std::vector<VirtualLight> lights = shoot_virtual_lights(scene, settings);
    const RGB white{1, 1, 1};
    const Vec3 up{0, 1, 0};
    long long every = 0, traced = 0;
    double dev_priority = 0, dev_every_ref = 0, dev_priority_ref = 0, norm_every = 0, norm_ref = 0;
    for (const Vec3& p : floor_points(scene.environment.room)) {
        const IndirectGather all = gather_virtual_lights(scene, lights, settings, white, p, up, false);
        const IndirectGather some = gather_virtual_lights(scene, lights, settings, white, p, up, true);
        const double reference = mean(effect.cpu_surface_light(scene, white, p, up));
        every += all.shadow_rays;
        traced += some.shadow_rays;
        const double a = mean(all.radiance), b = mean(some.radiance);
        dev_priority += (b - a) * (b - a);
        dev_every_ref += (a - reference) * (a - reference);
        dev_priority_ref += (b - reference) * (b - reference);
        norm_every += a * a;
        norm_ref += reference * reference;
    }
    const auto ratio = [](double num, double den) { return den > 0 ? std::sqrt(num / den) : 0.0; };
    Json j;
    j["virtual_lights"] = lights.size();
    j["points"] = floor_points(scene.environment.room).size();
    j["shadow_rays_every_sample"] = every;
    j["shadow_rays_priority"] = traced;
    j["shadow_rays_saved"] = every > 0 ? 1.0 - static_cast<double>(traced) / static_cast<double>(every) : 0.0;
    j["priority_vs_every_sample_rel_rms"] = ratio(dev_priority, norm_every);
    j["every_sample_vs_reference_rel_rms"] = ratio(dev_every_ref, norm_ref);
    j["priority_vs_reference_rel_rms"] = ratio(dev_priority_ref, norm_ref);
    return j;
}

class IndirectEffect final : public Effect {
public:
    std::string_view name() const override { return "indirect"; }

    std::vector<const char*> scene_keys() const override { return {"indirect"}; }
    void read_scene(const SceneReader& top, Scene& scene) const override {
        if (top.has("indirect")) scene.effects.set(read_indirect_settings(top));
    }

    void declare_environment_program(const Scene& scene, ShaderBuilder& builder) const override {
        if (!asked(scene)) return;
        builder.define("ENVIRONMENT_INDIRECT", "indirect_on_surface")
            .source(shader_text("room_face.glsl"))
            .source(shader_text("indirect.glsl"))
            .sampler("u_virtual_lights")
            .sampler("u_indirect_light");
    }

    void set_program_uniforms(const Scene& scene, GLuint p) const override {
        if (!asked(scene)) return;
        const IndirectSettings& settings = *scene.effects.find<IndirectSettings>();
        set_uniform(p, "u_indirect_clamp", static_cast<float>(settings.clamp_distance));
        set_uniform(p, "u_indirect_rate", static_cast<float>(settings.evaluation_rate));
        set_uniform(p, "u_indirect_room_min", scene.environment.room.min);
        set_uniform(p, "u_indirect_room_max", scene.environment.room.max);
        const int spheres = static_cast<int>(std::min<std::size_t>(scene.spheres.size(), 256));
        set_uniform(p, "u_indirect_sphere_count", spheres);
        for (int i = 0; i < spheres; ++i) {
            const Sphere& s = scene.spheres[static_cast<std::size_t>(i)];
            glProgramUniform4f(p, glGetUniformLocation(p, ("u_indirect_spheres[" + std::to_string(i) + "]").c_str()),
                               float(s.center.x), float(s.center.y), float(s.center.z), float(s.radius));
        }
        const auto& boxes = scene.environment.room.boxes;
        set_uniform(p, "u_indirect_box_count", static_cast<int>(boxes.size()));
        for (std::size_t i = 0; i < boxes.size(); ++i) {
            set_uniform(p, ("u_indirect_box_min[" + std::to_string(i) + "]").c_str(), boxes[i].min);
            set_uniform(p, ("u_indirect_box_max[" + std::to_string(i) + "]").c_str(), boxes[i].max);
        }
    }

    void bind_environment_program(GpuRenderer& renderer, const BuiltProgram& program) const override {
        if (!program.reads("u_indirect_light") || making_indirect_light(renderer)) return;
        const RoomLightMaps* maps = renderer.frame().find<RoomLightMaps>(kIndirectLightName);
        if (!maps) {  // no graph handed them over: shot and gathered here once
            auto& own = renderer.frame().state<OwnIndirectMaps>();
            if (!own.maps) {
                const IndirectSettings& settings = *renderer.scene().effects.find<IndirectSettings>();
                own.maps = RoomLightMaps::create({settings.light_map_size});
                render_indirect_light_maps(renderer, shoot_virtual_lights(renderer.scene(), settings), *own.maps);
            }
            maps = &*own.maps;
        }
        program.bind("u_indirect_light", maps->texture.id());
    }

    void add_frame_input_passes(PreviewGraph& g) const override {
        const std::string why = why_not(g.scene);
        if (!why.empty()) {
            if (g.scene.effects.find<IndirectSettings>()) g.graph.skip("virtual-lights", why);
            return;  // a scene that asks for no indirect light plans exactly the passes it did before
        }
        const IndirectSettings settings = *g.scene.effects.find<IndirectSettings>();
        const Scene& scene = g.scene;
        const Handle<VirtualLightSet> lights =
            g.graph
                .add_pass<Out<VirtualLightSet>>(
                    {"virtual-lights",
                     "the scene asks for 'indirect': " + std::to_string(settings.paths) +
                         " light paths per light, stored at their first diffuse room surface (rings reflect them), "
                         "gathered by the room's surfaces with the priority scheme's shadow rays",
                     Processor::cpu},
                    [&](Builder& b, Out<VirtualLightSet>& d) {
                        b.read(g.in.environment);
                        b.read(g.in.materials);
                        d.out = b.produce<VirtualLightSet>("virtual-lights");
                    },
                    [&scene, settings](const Out<VirtualLightSet>& d, Resources& r) {
                        r.emplace(d.out, VirtualLightSet{shoot_virtual_lights(scene, settings)});
                    })
                .out;
        struct Data {
            Handle<RoomLightMaps> out;
        };
        PreviewRun* run = g.run;
        const Handle<RoomLightMaps> maps =
            g.graph
                .add_pass<Data>(
                    {"indirect-light-maps",
                     "the virtual lights gathered per texel of six " + std::to_string(settings.light_map_size) +
                         "² room-face light maps, shadow rays for the largest potentials holding " +
                         glsl_float(settings.evaluation_rate) + " of each texel's total",
                     Processor::gpu},
                    [&](Builder& b, Data& d) {
                        b.read(lights);
                        d.out = b.create<RoomLightMaps>("indirect-light-maps", {settings.light_map_size});
                    },
                    [run, lights](const Data& d, Resources& r) {
                        render_indirect_light_maps(run->renderer(), r.get(lights).lights, r.get(d.out));
                    })
                .out;
        g.frame.add(maps, kIndirectLightName);
        g.environment.add(maps, kIndirectLightName);
    }

    // metrics.json's "indirect": over the floor, the shadow rays the priority scheme traced against every sample's, and
    // what leaving the others out cost (relative RMS against the gather with every shadow ray), both against the
    // Monte-Carlo reference.
    void add_output_passes(PreviewGraph& g) const override {
        if (!asked(g.scene) || !g.scene.outputs.metrics) return;
        const Scene& scene = g.scene;
        const Effect* self = this;
        const Handle<Json> figures =
            g.graph
                .add_pass<Out<Json>>(
                    {"indirect-figures",
                     "metrics.json's indirect: the priority scheme's shadow rays and error over "
                     "24 × 24 floor points, against every sample's and the Monte-Carlo reference",
                     Processor::cpu},
                    [&](Builder& b, Out<Json>& d) {
                        b.read(g.in.environment);
                        b.read(g.in.materials);
                        d.out = b.produce<Json>("indirect-figures");
                    },
                    [&scene, self](const Out<Json>& d, Resources& r) {
                        r.emplace(d.out, indirect_figures(scene, *self));
                    })
                .out;
        g.handles.effect_metrics.push_back({"indirect", figures});
    }

    // The CPU reference: one more diffuse bounce by Monte Carlo — cosine-weighted directions from p to the room
    // surface they meet, whose reflected light of every other effect (the lights, the caustics) comes back.
    bool lights_cpu_reference(const Scene& scene) const override { return asked(scene); }
    RGB cpu_surface_light(const Scene& scene, const RGB& albedo, Vec3 p, Vec3 n) const override {
        const IndirectSettings& settings = *scene.effects.find<IndirectSettings>();
        const Rings* rings = scene.effects.find<Rings>();
        std::uint64_t seed = 0x9E3779B97F4A7C15ull;
        for (const double c : {p.x, p.y, p.z}) {
            std::uint64_t bits = 0;
            std::memcpy(&bits, &c, sizeof bits);
            seed = (seed ^ bits) * 0x100000001B3ull;
        }
        std::mt19937_64 random(seed);
        std::uniform_real_distribution<double> uniform(0.0, 1.0);
        const int k = settings.reference_samples;
        const int side = std::max(1, static_cast<int>(std::sqrt(static_cast<double>(k))));
        RGB sum{0, 0, 0};
        const Vec3 o = p + 1e-6 * n;
        for (int s = 0; s < k; ++s) {
            // Stratified over a side × side grid while it lasts, then plain.
            const double u1 = s < side * side ? ((s / side) + uniform(random)) / side : uniform(random);
            const double u2 = s < side * side ? ((s % side) + uniform(random)) / side : uniform(random);
            const Vec3 d = cosine_direction(n, u1, u2);
            RGB q_albedo{0, 0, 0};
            Vec3 q, q_normal;
            bool diffuse = false;
            const EnvironmentTracer tracer(scene.environment, nullptr, [&](const RGB& a, Vec3 at, Vec3 normal) {
                q_albedo = a;
                q = at;
                q_normal = normal;
                diffuse = true;
                return RGB{0, 0, 0};
            });
            const double t = tracer.trace(o, d).t;
            if (!diffuse) continue;  // a ceiling panel: its emission is the room's own, not the lights'
            if (nearest_sphere(scene.spheres, o, d).t < t) continue;
            if (rings && intersect_rings(rings->rings, o, d, 1e-9, t)) continue;
            for (const Effect* effect : all_effects())
                if (effect != this && effect->lights_cpu_reference(scene))
                    sum = sum + effect->cpu_surface_light(scene, q_albedo, q, q_normal);
        }
        return (1.0 / k) * RGB{albedo.r * sum.r, albedo.g * sum.g, albedo.b * sum.b};
    }
};

}  // namespace

const Effect& indirect_effect() {
    static const IndirectEffect effect;
    return effect;
}

}  // namespace metalfit::glpreview
