#include "environment_effect.hpp"

#include <algorithm>

#include "glpreview/gl/uniforms.hpp"
#include "glpreview/render/frame_inputs.hpp"
#include "glpreview/render/gpu_renderer.hpp"
#include "glpreview/render/preview_passes.hpp"
#include "glpreview/render/scene_colour.hpp"

namespace metalfit::glpreview {

using graph::Builder;
using graph::Handle;
using graph::PassGraph;
using graph::Processor;
using graph::Resources;

namespace {

void set_environment_uniforms(const Environment& env, GLuint p) {
    set_uniform(p, "u_reference", env.reference());
    if (env.type == EnvironmentType::room) {
        const Room& room = env.room;
        set_uniform(p, "u_room_min", room.min);
        set_uniform(p, "u_room_max", room.max);
        set_uniform(p, "u_wall_x_min", room.wall_x_min);
        set_uniform(p, "u_wall_x_max", room.wall_x_max);
        set_uniform(p, "u_wall_z_min", room.wall_z_min);
        set_uniform(p, "u_wall_z_max", room.wall_z_max);
        set_uniform(p, "u_floor_light", room.floor_light);
        set_uniform(p, "u_floor_dark", room.floor_dark);
        set_uniform(p, "u_ceiling", room.ceiling);
        set_uniform(p, "u_checker", static_cast<float>(room.checker));
        const int panels = static_cast<int>(std::min<std::size_t>(room.panels.size(), 16));
        set_uniform(p, "u_panel_count", panels);
        for (int i = 0; i < panels; ++i) {
            const CeilingPanel& panel = room.panels[static_cast<std::size_t>(i)];
            const std::string index = "[" + std::to_string(i) + "]";
            glProgramUniform4f(p, glGetUniformLocation(p, ("u_panel_rect" + index).c_str()), float(panel.min_x),
                               float(panel.min_z), float(panel.max_x), float(panel.max_z));
            set_uniform(p, ("u_panel_radiance" + index).c_str(), panel.radiance);
        }
        const int boxes = static_cast<int>(std::min<std::size_t>(room.boxes.size(), 32));
        set_uniform(p, "u_box_count", boxes);
        for (int i = 0; i < boxes; ++i) {
            const RoomBox& box = room.boxes[static_cast<std::size_t>(i)];
            const std::string index = "[" + std::to_string(i) + "]";
            set_uniform(p, ("u_box_min" + index).c_str(), box.min);
            set_uniform(p, ("u_box_max" + index).c_str(), box.max);
            set_uniform(p, ("u_box_color" + index).c_str(), box.color);
        }
    } else if (env.type == EnvironmentType::sphere_room) {
        set_uniform(p, "u_sphere_room_radius", static_cast<float>(env.sphere_room.radius));
        set_uniform(p, "u_sphere_room_checker", static_cast<float>(env.sphere_room.checker_deg));
        set_uniform(p, "u_sphere_room_light", env.sphere_room.light);
        set_uniform(p, "u_sphere_room_dark", env.sphere_room.dark);
    } else {
        set_uniform(p, "u_equirect_intensity", static_cast<float>(env.equirect.intensity));
        if (env.equirect.proxy) {
            if (const auto* sphere = std::get_if<SphereProxy>(&*env.equirect.proxy)) {
                set_uniform(p, "u_proxy_radius", static_cast<float>(sphere->radius));
            } else {
                const auto& box = std::get<BoxProxy>(*env.equirect.proxy);
                set_uniform(p, "u_proxy_min", box.min - env.reference());
                set_uniform(p, "u_proxy_max", box.max - env.reference());
            }
        }
    }
    if (const auto box = env.parallax_box()) {  // the room's box or the equirect's box proxy
        set_uniform(p, "u_box_parallax_min", box->min - env.reference());
        set_uniform(p, "u_box_parallax_max", box->max - env.reference());
    }
}

class EnvironmentEffect final : public Effect {
public:
    std::string_view name() const override { return "environment"; }

    void add_frame_input_passes(PreviewGraph& g) const override {
        const EnvironmentInputs environment = add_environment_passes(g.graph, g.scene, g.features, g.in, g.run);
        g.handles.environment = environment;
        g.frame.add([environment](Builder& b) { environment.declare(b); },
                    [environment](GpuRenderer& gpu, Resources& r) { environment.bind(gpu, r); });
    }

    void set_program_uniforms(const Scene& scene, GLuint program) const override {
        set_environment_uniforms(scene.environment, program);
    }
};

}  // namespace

const Effect& environment_effect() {
    static const EnvironmentEffect effect;
    return effect;
}

namespace {
// What the capture ray-casts: "procedural room", or "equirect on its box proxy".
std::string captured_environment_name(const Environment& environment) {
    if (environment.type != EnvironmentType::equirect) return std::string("procedural ") + to_string(environment.type);
    if (const auto* sphere = std::get_if<SphereProxy>(&*environment.equirect.proxy))
        return "equirect on its sphere proxy (radius " + glsl_float(sphere->radius) + ")";
    return "equirect on its box proxy";
}
}  // namespace

Handle<EnvironmentCube> add_capture_environment_pass(PassGraph& graph, const Scene& scene, const Features& f,
                                                     const SceneInputs& in, PreviewRun* run,
                                                     std::optional<Handle<EquirectTexture>> equirect) {
    struct Data {
        std::optional<Handle<EquirectTexture>> equirect;
        Handle<EnvironmentCube> out;
    };
    return graph
        .add_pass<Data>(
            {"capture-environment",
             captured_environment_name(scene.environment) + ": ray-cast by GL into a " +
                 std::to_string(scene.environment.cube_size) + "² cube map (radiance" + (f.distance_channel ? " + distance" : "") +
                 ")" + (f.prefiltered_map ? " with a mip chain for the prefilter" : "") + ", once, reused by every frame",
             Processor::gpu},
            [&](Builder& b, Data& d) {
                b.read(in.environment);
                if (equirect) d.equirect = b.read(*equirect);
                d.out = b.create<EnvironmentCube>("environment-cube", {scene.environment.cube_size, f.distance_channel, f.prefiltered_map});
            },
            [run](const Data& d, Resources& r) {
                if (d.equirect) run->renderer().use_equirect(r.get(*d.equirect));
                run->renderer().capture_environment(r.get(d.out));
            })
        .out;
}

std::pair<Handle<EquirectTexture>, Handle<Image>> add_load_equirect_pass(PassGraph& graph, const Scene& scene, PreviewRun* run) {
    struct Data {
        Handle<EquirectTexture> texture;
        Handle<Image> image;
    };
    const Equirect& equirect = scene.environment.equirect;
    const Data& d = graph.add_pass<Data>(
        {"load-equirect",
         std::string(equirect.proxy ? "environment image on a proxy: " : "environment at infinity: ") + equirect.file.string() + " (OpenImageIO)" +
             (equirect.colorspace.empty() ? std::string(", taken as the scene's space (untagged)")
                                          : ", from " + equirect.colorspace + " into the scene's space"),
         Processor::cpu},
        [](Builder& b, Data& d) {
            d.texture = b.produce<EquirectTexture>("equirect-texture");
            d.image = b.produce<Image>("equirect-image");
        },
        [&scene, run](const Data& d, Resources& r) {
            const Image& image = r.emplace(d.image, read_environment_image(scene, run->ocio));
            r.emplace(d.texture, std::make_shared<const Image>(image));
        });
    return {d.texture, d.image};
}

void EnvironmentInputs::declare(Builder& b) const {
    if (cube) b.read(*cube);
    if (equirect_texture) b.read(*equirect_texture);
}

void EnvironmentInputs::bind(GpuRenderer& gpu, Resources& r) const {
    if (cube) gpu.use_environment(r.get(*cube));
    if (equirect_texture) gpu.use_equirect(r.get(*equirect_texture));
}

EnvironmentInputs add_environment_passes(PassGraph& graph, const Scene& scene, const Features& f, const SceneInputs& in,
                                         PreviewRun* run) {
    EnvironmentInputs environment;
    if (f.equirect_image) {
        const auto [texture, image] = add_load_equirect_pass(graph, scene, run);
        environment.equirect_texture = texture;
        environment.equirect_image = image;
    }
    if (f.environment_capture) {
        environment.cube = add_capture_environment_pass(graph, scene, f, in, run, environment.equirect_texture);
        if (!f.distance_channel)
            graph.skip("distance channel", "no sphere uses the distance impostor: the cube map stores radiance only (RGBA16F)");
    } else {
        graph.skip("capture-environment", "the environment is an image at infinity: nothing to capture");
    }
    return environment;
}

}  // namespace metalfit::glpreview
