#include "glpreview/render/bounces_bench.hpp"

#include <memory>
#include <string>
#include <vector>

#include "glpreview/render/bounce_orders.hpp"
#include "glpreview/render/mirror_path.hpp"
#include "glpreview/render/sphere_fresnel.hpp"
#include "glpreview/render/sphere_intersection.hpp"
#include "glpreview/scene/camera.hpp"
#include "libfit/base/errors.hpp"
#include "libfit/fit/parameter_source.hpp"
#include "libfit/models/model.hpp"

namespace metalfit::glpreview {
namespace {

using Json = nlohmann::ordered_json;

Json error_json(const MaskedError& e) {
    return {{"rmse", e.rmse}, {"de2000_mean", e.de2000_mean}, {"de2000_p95", e.de2000_p95}};
}

// Over the pixels whose path reaches the order: their count too.
Json reaching_json(const MaskedError& e) {
    Json j = error_json(e);
    j["pixels"] = e.pixels;
    return j;
}

// `row` with e's fields added after its own.
Json with_error(Json row, const MaskedError& e) {
    row["rmse"] = e.rmse;
    row["de2000_mean"] = e.de2000_mean;
    row["de2000_p95"] = e.de2000_p95;
    return row;
}

}  // namespace

Scene bounces_bench_scene(bool quick) {
    Scene scene;
    scene.file = "bench-bounces";  // built in: named in messages
    scene.width = quick ? 96 : 256;
    scene.height = quick ? 72 : 192;
    scene.camera.position = {0.0, 1.5, 2.4};
    scene.camera.look_at = {0.0, 0.45, 0.0};
    scene.camera.fov_y_deg = 40;
    scene.camera_position_given = true;
    scene.environment.room.panels.push_back({-0.8, -0.8, 0.8, 0.8, RGB{6, 6, 6}});
    const char* metals[] = {"Au", "Cu", "Ag", "Al"};
    const Vec3 centres[] = {{-0.45, 0.45, 0.45}, {0.45, 0.45, 0.45}, {-0.45, 0.45, -0.45}, {0.45, 0.45, -0.45}};
    for (int i = 0; i < 4; ++i) {
        Sphere s;
        s.center = centres[i];
        s.radius = 0.4;
        s.material = metals[i];
        s.reflection = ReflectionMode::classic;
        scene.spheres.push_back(s);
    }
    return scene;
}

Json bench_bounces(const PreviewOptions& options, bool quick) {
    const Scene scene = bounces_bench_scene(quick);
    FresnelLibrary library(options.data_dir, options.ocio, scene.space, scene.file);
    const DeltaEBasis basis = delta_e_basis(library.converter());
    const EnvironmentTracer tracer(scene.environment);
    BounceFresnel reference;
    std::vector<std::unique_ptr<SpectralFresnel>> spectral;
    for (std::size_t i = 0; i < scene.spheres.size(); ++i) {
        const std::string field = "spheres[" + std::to_string(i) + "]";
        reference.own.push_back(&library.get(scene.spheres[i], field));
        spectral.push_back(
            std::make_unique<SpectralFresnel>(library.material(scene.spheres[i], field), library.colorimetry()));
        reference.spectral.push_back(spectral.back().get());
    }
    reference.reference = reference.own;
    const RgbUplift uplift(library.colorimetry(), library.converter());
    reference.uplift = &uplift;

    Json j;
    j["scene"] = "Au, Cu, Ag, Al mirror spheres (radius 0.4, 0.1 apart in a 2x2 square) in the default room with a "
                 "ceiling panel";
    j["size"] = {scene.width, scene.height};
    j["orders"] = kBenchBounceOrders;
    j["rgb_vs_spectral"] = Json::array();
    std::vector<ReferenceRender> rgb, spectral_images, reach;
    for (int k = 1; k <= kBenchBounceOrders; ++k) {
        const BounceOrderRenders r = render_bounce_order(scene, reference, tracer, k, options.threads);
        reach.push_back(reaching_mask(scene, r.rgb, k));
        const MaskedError e = masked_errors(r.rgb.image, r.spectral.image, sphere_pixels_mask(r.rgb), 1, basis).front();
        Json row = with_error({{"order", k}}, e);
        row["reaching"] = reaching_json(masked_errors(r.rgb.image, r.spectral.image, reach.back(), 1, basis).front());
        j["rgb_vs_spectral"].push_back(row);
        rgb.push_back(r.rgb);
        spectral_images.push_back(r.spectral);
    }
    j["rows"] = Json::array();
    j["skipped"] = Json::array();
    for (const Model* model : all_models()) {
        for (const ParameterSource params : {ParameterSource::fit, ParameterSource::closed}) {
            std::vector<const SphereFresnel*> own;
            try {
                for (std::size_t i = 0; i < scene.spheres.size(); ++i) {
                    Sphere s = scene.spheres[i];
                    s.fresnel = ModelFresnel{std::string(model->id()), params};
                    own.push_back(&library.get(s, "spheres[" + std::to_string(i) + "]"));
                }
            } catch (const InputError& e) {
                j["skipped"].push_back({{"model", model->id()}, {"params", to_string(params)}, {"why", e.what()}});
                continue;
            }
            for (int k = 1; k <= kBenchBounceOrders; ++k) {
                const ReferenceRender image = render_reference(scene, own, tracer, options.threads, nullptr, k);
                const ReferenceRender& against = rgb[static_cast<std::size_t>(k - 1)];
                const ReferenceRender mask = sphere_pixels_mask(against);
                const MaskedError e = masked_errors(image.image, against.image, mask, 1, basis).front();
                const MaskedError s =
                    masked_errors(image.image, spectral_images[static_cast<std::size_t>(k - 1)].image, mask, 1, basis)
                        .front();
                Json row = with_error({{"model", model->id()}, {"params", to_string(params)}, {"order", k}}, e);
                row["vs_spectral"] = error_json(s);
                const ReferenceRender& paths = reach[static_cast<std::size_t>(k - 1)];
                row["reaching"] = reaching_json(masked_errors(image.image, against.image, paths, 1, basis).front());
                row["reaching_vs_spectral"] = reaching_json(
                    masked_errors(image.image, spectral_images[static_cast<std::size_t>(k - 1)].image, paths, 1, basis)
                        .front());
                j["rows"].push_back(row);
            }
        }
    }
    return j;
}

}  // namespace metalfit::glpreview
