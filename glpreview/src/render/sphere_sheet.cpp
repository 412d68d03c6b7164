#include "glpreview/render/sphere_sheet.hpp"

#include <cmath>
#include <optional>
#include <stdexcept>

#include "glpreview/render/gpu_renderer.hpp"
#include "glpreview/render/sphere_fresnel.hpp"
#include "glpreview/render/sphere_metrics.hpp"
#include "libfit/base/errors.hpp"

namespace metalfit::glpreview {
namespace {

void paste(Image& sheet, const Image& cell, int column, int row) {
    for (int y = 0; y < cell.height; ++y)
        for (int x = 0; x < cell.width; ++x) sheet.set(column * cell.width + x, row * cell.height + y, cell.at(x, y));
}

}  // namespace

SphereSheet render_sphere_sheet(const Scene& base, const std::vector<std::string>& materials, const PreviewOptions& options,
                                GlContext&) {
    if (base.spheres.size() != 1) throw InputError(InputLocation(base.file, 0, "spheres"), "a sheet scene holds exactly one sphere");
    FresnelLibrary library(options.data_dir, options.ocio, base.file);
    Scene scene = base;
    // One renderer and one capture for the whole sheet: only the sphere's material and Fresnel change.
    std::optional<GpuRenderer> gpu;
    SphereSheet sheet{Image(3 * scene.width, static_cast<int>(materials.size()) * scene.height), nlohmann::ordered_json::array()};
    for (std::size_t row = 0; row < materials.size(); ++row) {
        Sphere sphere = base.spheres[0];
        sphere.material = materials[row];
        sphere.fresnel = "reference";
        const SphereFresnel& reference = library.get(sphere, "sheet material " + materials[row]);
        sphere.fresnel = library.best_model(materials[row]);
        sphere.params = "fit";
        const SphereFresnel& model = library.get(sphere, "sheet material " + materials[row]);

        if (!gpu) {
            gpu.emplace(scene, plan_features(scene), std::vector<const SphereFresnel*>{&reference}, nullptr);
            gpu->capture_environment();
        }
        scene.spheres[0].fresnel = "reference";
        gpu->set_fresnel(0, &reference);
        const Image reference_image = gpu->render();
        scene.spheres[0].fresnel = model.fresnel;
        gpu->set_fresnel(0, &model);
        const Image model_image = gpu->render();
        const Image difference = absolute_difference(model_image, reference_image, kSheetDifferenceScale);

        paste(sheet.image, reference_image, 0, static_cast<int>(row));
        paste(sheet.image, model_image, 1, static_cast<int>(row));
        paste(sheet.image, difference, 2, static_cast<int>(row));
        double squared = 0;
        for (std::size_t i = 0; i < model_image.rgb.size(); ++i) {
            const double d = double(model_image.rgb[i]) - double(reference_image.rgb[i]);
            squared += d * d;
        }
        sheet.record.push_back({{"row", row},
                                {"material", model.material},
                                {"source", model.source},
                                {"model", model.fresnel},
                                {"model_worst_rel_rms", model.worst_rel_rms},
                                {"image_rmse_model_vs_reference", std::sqrt(squared / double(model_image.rgb.size()))}});
    }
    return sheet;
}

}  // namespace metalfit::glpreview
