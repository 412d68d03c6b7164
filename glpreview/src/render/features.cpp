#include "glpreview/render/features.hpp"

#include <algorithm>
#include <cmath>

#include "glpreview/render/sphere_shader.hpp"
#include "libfit/base/number_text.hpp"
#include "libfit/base/text.hpp"

namespace metalfit::glpreview {
const char* environment_define(const Environment& environment) {
    switch (environment.type) {
        case EnvironmentType::room: return "ENV_ROOM";
        case EnvironmentType::sphere_room: return "ENV_SPHERE_ROOM";
        case EnvironmentType::equirect:
            if (!environment.equirect.proxy) return "ENV_EQUIRECT";
            return std::holds_alternative<BoxProxy>(*environment.equirect.proxy) ? "ENV_EQUIRECT_BOX"
                                                                                 : "ENV_EQUIRECT_SPHERE";
    }
    return "";
}

const char* strategy_define(Strategy strategy) {
    switch (strategy) {
        case Strategy::secant: return "STRATEGY_SECANT";
        case Strategy::false_position: return "STRATEGY_FALSE_POSITION";
        case Strategy::mixed: return "STRATEGY_MIXED";
        case Strategy::illinois: return "STRATEGY_ILLINOIS";
        case Strategy::safe_secant: return "STRATEGY_SAFE_SECANT";
    }
    return "";
}

std::string glsl_float(double value) {
    std::string s = significant_text(value, 9);
    if (s.find_first_of(".e") == std::string::npos) s += ".0";
    return s;
}

std::vector<std::string> sphere_defines(const Scene& scene, const Sphere& sphere) {
    return sphere_shader(scene, sphere, nullptr).labels();
}

int localized_subdivisions(double roughness, int m) {
    const double alpha = roughness * roughness;
    const int most = (16 + m - 1) / m;
    if (alpha <= 0) return most;
    return static_cast<int>(std::clamp(std::round(6.0 / (alpha * m)), 1.0, static_cast<double>(most)));
}

void add_glossy_features(Features& f, const Sphere& s) {
    if (!s.rough()) return;
    if (s.glossy == GlossyMethod::localized) {
        f.distance_channel = true;  // the area lights' positions
        f.downsample_sizes.insert(s.localized_size);
    } else {
        f.prefiltered_map = true;
        f.dfg_models.insert(fresnel_name(s.fresnel));
    }
}

Features plan_features(const Scene& scene) {
    Features f;
    const auto type = scene.environment.type;
    f.environment_capture = scene.environment.captured();
    f.equirect_image = type == EnvironmentType::equirect;
    for (const Sphere& s : scene.spheres) {
        if (s.reflection == ReflectionMode::distance_impostor) f.distance_channel = true;
        add_glossy_features(f, s);
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
    f.fit_error = f.model_fits && (o.difference || o.metrics);
    f.localization_image = o.localization;
    f.cpu_reference = o.reference || o.difference || o.metrics;
    f.monte_carlo_reference = f.cpu_reference && std::any_of(scene.spheres.begin(), scene.spheres.end(),
                                                             [](const Sphere& s) { return s.rough(); });
    return f;
}

}  // namespace metalfit::glpreview
