#include "glpreview/render/reflection_probe.hpp"

#include "glpreview/render/environment.hpp"
#include "glpreview/render/output_staging.hpp"
#include "glpreview/render/scene_colour.hpp"
#include "libfit/base/atomic_file.hpp"
#include "libfit/base/errors.hpp"
#include "libfit/base/input_file.hpp"
#include "libfit/color/chromaticities.hpp"

namespace metalfit::glpreview {
namespace {

using Json = nlohmann::ordered_json;

Json to_json(Vec3 v) { return Json::array({v.x, v.y, v.z}); }

// The proxy the probe is painted on: the geometry the environment's radiance comes from, seen from the capture point.
Json proxy_of(const Environment& environment) {
    switch (environment.type) {
        case EnvironmentType::room:
            return {{"box", {{"min", to_json(environment.room.min)}, {"max", to_json(environment.room.max)}}}};
        case EnvironmentType::sphere_room: return {{"sphere", environment.sphere_room.radius}};
        case EnvironmentType::equirect: break;
    }
    if (const auto* box = std::get_if<BoxProxy>(&*environment.equirect.proxy))
        return {{"box", {{"min", to_json(box->min)}, {"max", to_json(box->max)}}}};
    return {{"sphere", std::get<SphereProxy>(*environment.equirect.proxy).radius}};
}

}  // namespace

ReflectionProbe capture_probe(const Scene& scene, const OcioConfigChoice& ocio, int width, int height) {
    const Environment& environment = scene.environment;
    if (!environment.captured())
        throw UsageError(
            "--capture-probe: the scene's environment is an image at infinity, which has no proxy to capture "
            "onto (give it environment.proxy, or capture a room)");
    ReflectionProbe probe;
    const ColorSpaceConverter space = scene_converter(ocio, scene.space, scene.file);
    probe.colour = ExrColour{chromaticities_of(space), space.space()};
    // An equirect on a proxy is traced as the renderer sees it: its pixels converted into the scene's space.
    const Image equirect =
        environment.type == EnvironmentType::equirect ? read_environment_image(scene, ocio) : Image();
    const EnvironmentTracer tracer(environment, &equirect);
    const Vec3 capture_point = environment.reference();
    probe.image = capture_equirect(tracer, capture_point, width, height);

    probe.scene = Json::parse(read_input_file(scene.file));
    probe.scene["environment"] = Json{{"type", "equirect"},
                                      {"file", "probe.exr"},
                                      {"colorspace", probe.colour.space},
                                      {"reference_point", to_json(capture_point)},
                                      {"cube_size", environment.cube_size},
                                      {"proxy", proxy_of(environment)}};
    return probe;
}

std::vector<std::filesystem::path> write_probe(const ReflectionProbe& probe, const std::filesystem::path& output_dir) {
    OutputStaging staging(output_dir);
    write_exr(staging.file("probe.exr"), probe.image, &probe.colour);
    write_file_atomically(staging.file("probe.json"), probe.scene.dump(2) + "\n");
    staging.commit();
    return {output_dir / "probe.exr", output_dir / "probe.json"};
}

}  // namespace metalfit::glpreview
