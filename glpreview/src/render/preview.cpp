#include "glpreview/render/preview.hpp"

#include "frame_timing.hpp"
#include "glpreview/render/environment.hpp"
#include "glpreview/render/gpu_renderer.hpp"
#include "glpreview/io/image_io.hpp"
#include "glpreview/render/sphere_fresnel.hpp"
#include "glpreview/render/sphere_metrics.hpp"
#include "libfit/base/atomic_file.hpp"
#include "libfit/base/errors.hpp"

namespace metalfit::glpreview {
namespace {

nlohmann::ordered_json metrics_json(const Scene& scene, const PreviewResult& r, const std::vector<const SphereFresnel*>& fresnel) {
    nlohmann::ordered_json j;
    j["schema"] = "metalfit.preview-metrics/1";
    j["scene"] = scene.file.filename().string();
    j["renderer"] = r.renderer;
    j["size"] = {scene.width, scene.height};
    j["ms_per_frame"] = r.frame_ms.empty() ? 0.0 : median(r.frame_ms);
    j["frame_ms"] = r.frame_ms;
    const auto errors = sphere_errors(*r.beauty, *r.reference, scene.spheres.size());
    j["spheres"] = nlohmann::ordered_json::array();
    for (std::size_t i = 0; i < scene.spheres.size(); ++i) {
        const Sphere& s = scene.spheres[i];
        const bool impostor = s.reflection == ReflectionMode::distance_impostor;
        nlohmann::ordered_json e;
        e["sphere"] = i;
        e["material"] = fresnel[i]->material;
        e["source"] = fresnel[i]->source;
        e["fresnel"] = s.fresnel;
        e["params"] = s.fresnel == "reference" ? nlohmann::ordered_json(nullptr) : nlohmann::ordered_json(s.params);
        e["mode"] = to_string(s.reflection);
        e["strategy"] = impostor ? nlohmann::ordered_json(to_string(s.strategy)) : nlohmann::ordered_json(nullptr);
        e["iterations"] = impostor ? s.iterations : 0;
        e["rmse"] = errors[i].rmse;
        e["mean_abs"] = errors[i].mean_abs;
        e["pixels"] = errors[i].pixels;
        j["spheres"].push_back(e);
    }
    return j;
}

}  // namespace

PreviewResult run_preview(const Scene& scene, const PreviewOptions& options, GlContext* context) {
    PreviewResult result;
    result.plan = build_plan(scene);
    const Plan& plan = result.plan;

    FresnelLibrary library(options.data_dir, options.ocio, scene.file);
    std::vector<const SphereFresnel*> fresnel;
    for (std::size_t i = 0; i < scene.spheres.size(); ++i)
        fresnel.push_back(&library.get(scene.spheres[i], "spheres[" + std::to_string(i) + "]"));

    std::optional<Image> equirect;
    if (plan.runs("load-equirect")) equirect = read_image(scene.environment.equirect.file);
    const Image* equirect_ptr = equirect ? &*equirect : nullptr;

    if (plan.runs("beauty") || plan.runs("timing")) {
        std::optional<GlContext> own;
        if (!context) context = &own.emplace(GlContext::create());
        result.renderer = context->renderer();
        GpuRenderer gpu(scene, plan.features, fresnel, equirect_ptr);
        if (plan.runs("capture-environment")) gpu.capture_environment();
        if (plan.runs("beauty")) result.beauty = gpu.render();
        if (plan.runs("timing")) result.frame_ms = gpu.time_frames(scene.outputs.timing_frames);
    }
    if (plan.runs("cpu-reference")) {
        const EnvironmentTracer tracer(scene.environment, equirect_ptr);
        result.reference = render_reference(scene, fresnel, tracer, options.threads);
    }
    if (plan.runs("difference")) result.difference = absolute_difference(*result.beauty, result.reference->image);
    if (plan.runs("metrics")) result.metrics = metrics_json(scene, result, fresnel);

    if (options.output_dir.empty()) return result;
    std::error_code error;
    std::filesystem::create_directories(options.output_dir, error);
    if (error) throw InputError(InputLocation(options.output_dir), "cannot create the output folder: " + error.message());
    std::optional<DisplayTransform> display;
    if (scene.outputs.png) display = DisplayTransform::create(options.ocio);
    for (const std::string& file : plan.outputs) {
        const std::filesystem::path path = options.output_dir / file;
        const std::string stem = path.stem().string();
        if (file == "metrics.json") {
            write_file_atomically(path, result.metrics.dump(2) + "\n");
        } else {
            const Image& image = stem == "beauty" ? *result.beauty : stem == "reference" ? result.reference->image : *result.difference;
            if (path.extension() == ".exr") write_exr(path, image);
            else write_png(path, image, *display);
        }
        result.written.push_back(path);
    }
    return result;
}

}  // namespace metalfit::glpreview
