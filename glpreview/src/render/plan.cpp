#include "glpreview/render/plan.hpp"

#include <algorithm>
#include <map>
#include <sstream>

namespace metalfit::glpreview {
namespace {

std::string join(const std::vector<std::string>& items, const char* separator = ", ") {
    std::string text;
    for (const auto& item : items) text += (text.empty() ? "" : separator) + item;
    return text;
}

}  // namespace

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
    defines.push_back(sphere.fresnel == "reference" ? "FRESNEL_REFERENCE" : "FRESNEL_MODEL " + sphere.fresnel);
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
        if (s.fresnel == "reference") f.reference_lut = true;
        else {
            f.model_fits = true;
            f.models.insert(s.fresnel);
        }
        f.shader_variants.insert(join(sphere_defines(scene, s), " "));
    }
    const Outputs& o = scene.outputs;
    f.difference_image = o.difference;
    f.metrics = o.metrics;
    f.cpu_reference = o.reference || o.difference || o.metrics;
    return f;
}

bool Plan::runs(const std::string& pass_name) const {
    return std::any_of(passes.begin(), passes.end(), [&](const Pass& p) { return p.name == pass_name; });
}

Plan build_plan(const Scene& scene) {
    Plan plan;
    plan.features = plan_features(scene);
    const Features& f = plan.features;
    const Outputs& o = scene.outputs;
    std::vector<Pass> candidates;
    std::vector<SkippedPass>& skipped = plan.skipped;

    // Inputs of the GPU render.
    std::vector<std::string> beauty_reads{"camera"};
    if (f.environment_capture) {
        candidates.push_back({"capture-environment",
                              std::string("procedural ") + to_string(scene.environment.type) +
                                  ": ray-cast by GL into a " + std::to_string(scene.environment.cube_size) +
                                  "² cube map (radiance" + (f.distance_channel ? " + distance" : "") +
                                  "), once, reused by every frame",
                              {"environment-description"}, {"environment-cube"}, true});
        beauty_reads.push_back("environment-cube");
        if (!f.distance_channel)
            skipped.push_back({"distance channel", "no sphere uses the distance impostor: the cube map stores radiance only (RGBA16F)"});
    } else {
        skipped.push_back({"capture-environment", "the environment is an image at infinity: nothing to capture"});
    }
    if (f.equirect_image) {
        candidates.push_back({"load-equirect", "environment at infinity: " + scene.environment.equirect.file.string() + " (OpenImageIO)",
                              {}, {"equirect-texture", "equirect-image"}, false});
        beauty_reads.push_back("equirect-texture");
    }
    if (f.reference_lut) {
        candidates.push_back({"reference-luts", "some sphere shows the exact reference: R_c(μ) from libfit into 1D RGB textures (256 texels)",
                              {"materials"}, {"fresnel-luts"}, false});
        beauty_reads.push_back("fresnel-luts");
    } else {
        skipped.push_back({"reference-luts", "no sphere uses fresnel 'reference'"});
    }
    if (f.model_fits) {
        candidates.push_back({"model-parameters", "models " + join({f.models.begin(), f.models.end()}) +
                                                      ": parameters from libfit (Ceres fit or closed form)",
                              {"materials"}, {"model-parameters"}, false});
        beauty_reads.push_back("model-parameters");
    } else {
        skipped.push_back({"model-parameters", "no sphere uses a libfit model"});
    }
    candidates.push_back({"beauty", std::to_string(f.shader_variants.size()) + " sphere shader variant(s): " +
                                        join({f.shader_variants.begin(), f.shader_variants.end()}, " | "),
                          beauty_reads, {"beauty-image"}, true});
    std::vector<std::string> reference_reads{"camera"};
    if (f.equirect_image) reference_reads.push_back("equirect-image");
    if (f.reference_lut) reference_reads.push_back("fresnel-luts");
    if (f.model_fits) reference_reads.push_back("model-parameters");
    candidates.push_back({"cpu-reference", "analytic ray tracing of the same scene: exact mirror reflections, same Fresnel, same camera",
                          reference_reads, {"reference-image"}, false});
    candidates.push_back({"difference", "|beauty − reference| per pixel", {"beauty-image", "reference-image"}, {"difference-image"}, false});
    candidates.push_back({"timing", "ms per frame: median of " + std::to_string(o.timing_frames) + " frames between glFinish calls",
                          beauty_reads, {"frame-times"}, true});
    candidates.push_back({"metrics", "per sphere: RMSE and mean |difference| of linear radiance inside the sphere mask",
                          {"beauty-image", "reference-image", "frame-times"}, {"metrics"}, false});

    // Sinks: the files asked for.
    std::vector<std::string> formats;
    if (o.exr) formats.push_back("exr");
    if (o.png) formats.push_back("png");
    auto add_image_sinks = [&](bool wanted, const std::string& image, const std::string& name) {
        if (!wanted) return;
        for (const auto& format : formats) {
            const std::string file = name + "." + format;
            candidates.push_back({"write " + file, format == "png" ? "through the OCIO display transform" : "linear half-float EXR",
                                  {image}, {"file:" + file}, false});
            plan.outputs.push_back(file);
        }
    };
    add_image_sinks(o.beauty, "beauty-image", "beauty");
    add_image_sinks(o.reference, "reference-image", "reference");
    add_image_sinks(o.difference, "difference-image", "difference");
    if (o.metrics) {
        candidates.push_back({"write metrics.json", "asked for", {"metrics"}, {"file:metrics.json"}, false});
        plan.outputs.push_back("metrics.json");
    }

    // Cull: walk back from the files, keeping every pass that writes something a kept pass reads.
    std::set<std::string> needed;
    for (const Pass& p : candidates)
        for (const auto& w : p.writes)
            if (w.rfind("file:", 0) == 0) needed.insert(w);
    std::vector<bool> keep(candidates.size(), false);
    for (bool changed = true; changed;) {
        changed = false;
        for (std::size_t i = candidates.size(); i-- > 0;) {
            if (keep[i]) continue;
            const Pass& p = candidates[i];
            if (std::any_of(p.writes.begin(), p.writes.end(), [&](const std::string& w) { return needed.count(w) > 0; })) {
                keep[i] = true;
                changed = true;
                needed.insert(p.reads.begin(), p.reads.end());
            }
        }
    }
    for (std::size_t i = 0; i < candidates.size(); ++i) {
        if (keep[i]) plan.passes.push_back(candidates[i]);
        else skipped.push_back({candidates[i].name, "culled: nothing asked for reads " + join(candidates[i].writes)});
    }
    skipped.push_back({"prefiltered environment map", "every sphere is a perfect mirror (roughness 0)"});
    skipped.push_back({"SH irradiance", "metals have no diffuse lobe"});
    return plan;
}

std::string explain(const Plan& plan, const Scene& scene) {
    std::ostringstream out;
    out << "scene " << scene.file.string() << ": " << scene.width << "x" << scene.height << ", "
        << scene.spheres.size() << " sphere(s), environment " << to_string(scene.environment.type) << "\n";
    out << "passes:\n";
    int i = 1;
    for (const Pass& p : plan.passes) {
        out << "  " << i++ << ". " << p.name << (p.gpu ? " [GPU]" : " [CPU]") << ": " << p.why << "\n";
        if (!p.reads.empty()) out << "       reads " << join(p.reads) << "\n";
        out << "       writes " << join(p.writes) << "\n";
    }
    out << "skipped:\n";
    for (const SkippedPass& s : plan.skipped) out << "  - " << s.name << ": " << s.why << "\n";
    return out.str();
}

}  // namespace metalfit::glpreview
