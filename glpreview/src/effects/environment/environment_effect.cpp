#include "environment_effect.hpp"

#include <algorithm>
#include <cmath>

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

using Reader = SceneReader;

void check_box(const Reader& r, const char* what, const Vec3& min, const Vec3& max) {
    if (!(min.x < max.x && min.y < max.y && min.z < max.z))
        r.fail(r.field(what), "min must be below max on every axis");
}

Room read_room(const Reader& r) {
    Room room;
    r.read("min", room.min);
    r.read("max", room.max);
    check_box(r, "max", room.min, room.max);
    r.read_color("wall_x_min", room.wall_x_min);
    r.read_color("wall_x_max", room.wall_x_max);
    r.read_color("wall_z_min", room.wall_z_min);
    r.read_color("wall_z_max", room.wall_z_max);
    r.read_color("floor_light", room.floor_light);
    r.read_color("floor_dark", room.floor_dark);
    r.read_color("ceiling", room.ceiling);
    r.read("checker", room.checker, 1e-3, kSceneBig);
    bool panels_given = false;
    r.each("panels", [&](const nlohmann::json& v, const std::string& path) {
        panels_given = true;
        Reader p(v, path, r.file(), {"min", "max", "radiance"});
        CeilingPanel panel;
        auto read2 = [&](const char* key, double& a, double& b) {
            if (!p.has(key)) p.fail(p.field(key), "missing ([x, z])");
            const nlohmann::json& e = p.at(key);
            if (!e.is_array() || e.size() != 2 || !e[0].is_number() || !e[1].is_number())
                p.fail(p.field(key), "expected [x, z]");
            a = e[0].get<double>();
            b = e[1].get<double>();
        };
        read2("min", panel.min_x, panel.min_z);
        read2("max", panel.max_x, panel.max_z);
        if (!(panel.min_x < panel.max_x && panel.min_z < panel.max_z)) p.fail(p.field("max"), "min must be below max");
        p.read_color("radiance", panel.radiance);
        if (room.panels.size() >= kMaxPanels)
            r.fail(r.field("panels"), "at most " + std::to_string(kMaxPanels) + " panels");
        room.panels.push_back(panel);
    });
    if (!panels_given) {  // default: a 2 × 2 grid of panels over the room's middle
        const double cx = 0.5 * (room.min.x + room.max.x), cz = 0.5 * (room.min.z + room.max.z);
        const double sx = 0.15 * (room.max.x - room.min.x), sz = 0.15 * (room.max.z - room.min.z);
        for (int i : {-1, 1})
            for (int j : {-1, 1})
                room.panels.push_back({cx + i * sx - 0.4 * sx,
                                       cz + j * sz - 0.4 * sz,
                                       cx + i * sx + 0.4 * sx,
                                       cz + j * sz + 0.4 * sz,
                                       {6, 6, 6}});
    }
    r.each("boxes", [&](const nlohmann::json& v, const std::string& path) {
        Reader b(v, path, r.file(), {"min", "max", "color"});
        RoomBox box;
        if (!b.has("min") || !b.has("max")) b.fail(path, "a box needs min and max");
        b.read("min", box.min);
        b.read("max", box.max);
        check_box(b, "max", box.min, box.max);
        b.read_color("color", box.color);
        if (room.boxes.size() >= kMaxRoomBoxes)
            b.fail(path, "at most " + std::to_string(kMaxRoomBoxes) + " boxes and columns together");
        room.boxes.push_back(box);
    });
    r.each("columns", [&](const nlohmann::json& v, const std::string& path) {
        Reader c(v, path, r.file(), {"center", "half_width", "color"});
        if (!c.has("center")) c.fail(c.field("center"), "missing ([x, z])");
        const nlohmann::json& e = c.at("center");
        if (!e.is_array() || e.size() != 2 || !e[0].is_number() || !e[1].is_number())
            c.fail(c.field("center"), "expected [x, z]");
        double half = 0.2;
        c.read("half_width", half, 1e-3, kSceneBig);
        RoomBox box;
        box.min = {e[0].get<double>() - half, room.min.y, e[1].get<double>() - half};
        box.max = {e[0].get<double>() + half, room.max.y, e[1].get<double>() + half};
        c.read_color("color", box.color);
        if (room.boxes.size() >= kMaxRoomBoxes)
            c.fail(path, "at most " + std::to_string(kMaxRoomBoxes) + " boxes and columns together");
        room.boxes.push_back(box);
    });
    return room;
}

// "proxy": {"box": {"min": [..], "max": [..]}} or {"sphere": radius} (docs/scene.md, "Environments").
EnvironmentProxy read_proxy(const Reader& environment) {
    const Reader r(environment.at("proxy"), "environment.proxy", environment.file(), {"box", "sphere"});
    if (r.has("box") == r.has("sphere")) r.fail("environment.proxy", "expected exactly one of 'box' or 'sphere'");
    if (r.has("sphere")) {
        SphereProxy sphere;
        r.read("sphere", sphere.radius, 1e-3, kSceneBig);
        return sphere;
    }
    const Reader b(r.at("box"), "environment.proxy.box", environment.file(), {"min", "max"});
    BoxProxy box;
    for (const char* key : {"min", "max"})
        if (!b.has(key)) b.fail(b.field(key), "missing");
    b.read("min", box.min);
    b.read("max", box.max);
    for (int i = 0; i < 3; ++i) {
        if (std::abs(box.min[i]) > kSceneBig) b.fail(b.field("min"), "coordinates must be in [-1e+06, 1e+06]");
        if (std::abs(box.max[i]) > kSceneBig) b.fail(b.field("max"), "coordinates must be in [-1e+06, 1e+06]");
        if (!(box.max[i] - box.min[i] >= 1e-3))
            b.fail(b.field("max"), "must exceed min by at least 1e-3 on every axis");
    }
    return box;
}

class EnvironmentEffect final : public Effect {
public:
    std::string_view name() const override { return "environment"; }

    std::vector<const char*> scene_keys() const override { return {"environment"}; }

    void read_scene(const SceneReader& top, Scene& scene) const override {
        const std::filesystem::path& file = top.file();
        {
            static const nlohmann::json no_environment =
                nlohmann::json::object();  // the default room, with its default panels
            const nlohmann::json& env = top.has("environment") ? top.at("environment") : no_environment;
            Environment& e = scene.environment;
            std::string text = "room";
            if (env.is_object() && env.contains("type")) {
                if (!env["type"].is_string()) top.fail("environment.type", "expected a string");
                text = env["type"].get<std::string>();
            }
            const std::optional<EnvironmentType> type = kEnvironmentTypeNames.find(text);
            if (!type)
                top.fail("environment.type",
                         "unknown value '" + scene_excerpt(text) + "' (" + kEnvironmentTypeNames.known() + ")");
            if (type == EnvironmentType::room) {
                Reader r(env, "environment", file,
                         {"type", "reference_point", "cube_size", "min", "max", "wall_x_min", "wall_x_max",
                          "wall_z_min", "wall_z_max", "floor_light", "floor_dark", "ceiling", "checker", "panels",
                          "boxes", "columns"});
                e.type = EnvironmentType::room;
                e.room = read_room(r);
                r.read("cube_size", e.cube_size, 8, 4096);
                if (r.has("reference_point")) {
                    Vec3 p;
                    r.read("reference_point", p);
                    e.reference_point = p;
                    for (int i = 0; i < 3; ++i)
                        if (!(p[i] > e.room.min[i] && p[i] < e.room.max[i]))
                            r.fail("environment.reference_point", "must be inside the room");
                }
            } else if (type == EnvironmentType::sphere_room) {
                Reader r(env, "environment", file,
                         {"type", "reference_point", "cube_size", "radius", "checker_deg", "light", "dark"});
                e.type = EnvironmentType::sphere_room;
                r.read("radius", e.sphere_room.radius, 1e-3, kSceneBig);
                r.read("checker_deg", e.sphere_room.checker_deg, 0.1, 180);
                r.read_color("light", e.sphere_room.light);
                r.read_color("dark", e.sphere_room.dark);
                r.read("cube_size", e.cube_size, 8, 4096);
                if (r.has("reference_point")) {
                    Vec3 p;
                    r.read("reference_point", p);
                    e.reference_point = p;
                }
            } else {
                Reader r(env, "environment", file,
                         {"type", "file", "intensity", "colorspace", "proxy", "reference_point", "cube_size"});
                e.type = EnvironmentType::equirect;
                std::string path;
                r.read("file", path);
                if (path.empty()) r.fail("environment.file", "missing (an equirectangular EXR or HDR image)");
                e.equirect.file =
                    std::filesystem::path(path).is_absolute() ? std::filesystem::path(path) : file.parent_path() / path;
                r.read("intensity", e.equirect.intensity, 0, kSceneBig);
                if (r.has("colorspace")) r.read("colorspace", e.equirect.colorspace);
                if (r.has("proxy")) e.equirect.proxy = read_proxy(r);
                r.read("cube_size", e.cube_size, 8, 4096);
                if (r.has("reference_point")) {
                    Vec3 p;
                    r.read("reference_point", p);
                    e.reference_point = p;
                }
                if (const auto* box = e.equirect.proxy ? std::get_if<BoxProxy>(&*e.equirect.proxy) : nullptr) {
                    const Vec3 o = e.reference();
                    for (int i = 0; i < 3; ++i)
                        if (!(o[i] > box->min[i] && o[i] < box->max[i]))
                            r.fail(
                                r.has("reference_point") ? "environment.reference_point" : "environment.proxy.box",
                                "the capture point (environment.reference_point, default the origin) must lie inside the proxy box");
                }
                if (!e.equirect.proxy)
                    for (const char* key : {"reference_point", "cube_size"})
                        if (r.has(key))
                            scene.warnings.push_back(
                                file.string() + ": environment." + key +
                                ": ignored: an equirect without a proxy is at infinity (nothing is captured)");
            }
        }
    }

    void add_frame_input_passes(PreviewGraph& g) const override {
        const EnvironmentInputs environment =
            add_environment_passes(g.graph, g.scene, g.features, g.in, g.run, &g.environment);
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
                                                     std::optional<Handle<EquirectTexture>> equirect,
                                                     const FrameInputs* capture_inputs) {
    struct Data {
        std::optional<Handle<EquirectTexture>> equirect;
        Handle<EnvironmentCube> out;
    };
    return graph
        .add_pass<Data>(
            {"capture-environment",
             captured_environment_name(scene.environment) + ": ray-cast by GL into a " +
                 std::to_string(scene.environment.cube_size) + "² cube map (radiance" +
                 (f.distance_channel ? " + distance" : "") + ")" +
                 (f.prefiltered_map ? " with a mip chain for the prefilter" : "") + ", once, reused by every frame",
             Processor::gpu},
            [&](Builder& b, Data& d) {
                b.read(in.environment);
                if (equirect) d.equirect = b.read(*equirect);
                if (capture_inputs) capture_inputs->declare(b);
                d.out = b.create<EnvironmentCube>("environment-cube",
                                                  {scene.environment.cube_size, f.distance_channel, f.prefiltered_map});
            },
            [run, capture_inputs = capture_inputs ? std::optional<FrameInputs>(*capture_inputs)
                                                  : std::nullopt](const Data& d, Resources& r) {
                if (d.equirect) run->renderer().use_equirect(r.get(*d.equirect));
                if (capture_inputs) capture_inputs->bind(run->renderer(), r);
                run->renderer().capture_environment(r.get(d.out));
            })
        .out;
}

std::pair<Handle<EquirectTexture>, Handle<Image>> add_load_equirect_pass(PassGraph& graph, const Scene& scene,
                                                                         PreviewRun* run) {
    struct Data {
        Handle<EquirectTexture> texture;
        Handle<Image> image;
    };
    const Equirect& equirect = scene.environment.equirect;
    const Data& d = graph.add_pass<Data>(
        {"load-equirect",
         std::string(equirect.proxy ? "environment image on a proxy: " : "environment at infinity: ") +
             equirect.file.string() + " (OpenImageIO)" +
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
                                         PreviewRun* run, const FrameInputs* capture_inputs) {
    EnvironmentInputs environment;
    if (f.equirect_image) {
        const auto [texture, image] = add_load_equirect_pass(graph, scene, run);
        environment.equirect_texture = texture;
        environment.equirect_image = image;
    }
    if (f.environment_capture) {
        environment.cube =
            add_capture_environment_pass(graph, scene, f, in, run, environment.equirect_texture, capture_inputs);
        if (!f.distance_channel)
            graph.skip("distance channel",
                       "no sphere uses the distance impostor: the cube map stores radiance only (RGBA16F)");
    } else {
        graph.skip("capture-environment", "the environment is an image at infinity: nothing to capture");
    }
    return environment;
}

}  // namespace metalfit::glpreview
