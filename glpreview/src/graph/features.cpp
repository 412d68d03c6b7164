#include "glpreview/graph/features.hpp"

#include <algorithm>

#include "libfit/base/text.hpp"

namespace metalfit::glpreview {
const char* environment_define(EnvironmentType type) {
    switch (type) {
        case EnvironmentType::room: return "ENV_ROOM";
        case EnvironmentType::sphere_room: return "ENV_SPHERE_ROOM";
        case EnvironmentType::equirect: return "ENV_EQUIRECT";
    }
    return "";
}

std::vector<std::string> sphere_defines(const Scene& scene, const Sphere& sphere) {
    std::vector<std::string> defines{environment_define(scene.environment.type)};
    switch (sphere.reflection) {
        case ReflectionMode::classic: defines.push_back("REFLECTION_CLASSIC"); break;
        case ReflectionMode::box_parallax: defines.push_back("REFLECTION_BOX_PARALLAX"); break;
        case ReflectionMode::distance_impostor:
            defines.push_back("REFLECTION_DISTANCE_IMPOSTOR");
            defines.push_back(sphere.strategy == Strategy::secant           ? "STRATEGY_SECANT"
                              : sphere.strategy == Strategy::false_position ? "STRATEGY_FALSE_POSITION"
                                                                            : "STRATEGY_MIXED");
            defines.push_back("NITER " + std::to_string(sphere.iterations));
            break;
    }
    defines.push_back(shows_reference(sphere) ? "FRESNEL_REFERENCE" : "FRESNEL_MODEL " + fresnel_name(sphere.fresnel));
    std::sort(defines.begin(), defines.end());
    return defines;
}

Features plan_features(const Scene& scene) {
    Features f;
    const auto type = scene.environment.type;
    f.environment_capture = type == EnvironmentType::room || type == EnvironmentType::sphere_room;
    f.equirect_image = type == EnvironmentType::equirect;
    for (const Sphere& s : scene.spheres) {
        if (s.reflection == ReflectionMode::distance_impostor) f.distance_channel = true;
        if (const auto* model = std::get_if<ModelFresnel>(&s.fresnel)) {
            f.model_fits = true;
            f.models.insert(model->model);
        } else {
            f.reference_lut = true;
        }
        f.shader_variants.insert(join(sphere_defines(scene, s), " "));
    }
    const Outputs& o = scene.outputs;
    f.difference_image = o.difference;
    f.metrics = o.metrics;
    f.cpu_reference = o.reference || o.difference || o.metrics;
    return f;
}

}  // namespace metalfit::glpreview
