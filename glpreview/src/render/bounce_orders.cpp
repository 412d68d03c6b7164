#include "glpreview/render/bounce_orders.hpp"

#include "glpreview/render/mirror_path.hpp"
#include "glpreview/render/spectral_reference.hpp"
#include "glpreview/render/sphere_intersection.hpp"
#include "glpreview/render/sphere_metrics.hpp"
#include "glpreview/scene/camera.hpp"

namespace metalfit::glpreview {

BounceOrderRenders render_bounce_order(const Scene& scene, const BounceFresnel& fresnel,
                                       const EnvironmentTracer& environment, int order, int threads,
                                       const CpuLighting* lighting) {
    return {render_reference(scene, fresnel.own, environment, threads, lighting, order),
            render_reference(scene, fresnel.reference, environment, threads, lighting, order),
            render_spectral_reference(scene, fresnel.spectral, *fresnel.uplift, environment, order, threads, lighting)};
}

std::vector<MaskedError> masked_errors(const Image& image, const Image& reference, const ReferenceRender& mask,
                                       std::size_t spheres, const DeltaEBasis& basis) {
    const ReferenceRender against{reference, mask.sphere_id};
    const std::vector<SphereError> errors = sphere_errors(image, against, spheres);
    const std::vector<SphereDeltaE> delta_e = sphere_delta_e(delta_e_2000(image, reference, basis), against, spheres);
    std::vector<MaskedError> out(spheres);
    for (std::size_t s = 0; s < spheres; ++s)
        out[s] = {errors[s].rmse, delta_e[s].mean, delta_e[s].p95, errors[s].pixels};
    return out;
}

std::vector<SphereOrderError> bounce_order_errors(const BounceOrderRenders& r, std::size_t spheres,
                                                  const DeltaEBasis& basis) {
    const std::vector<MaskedError> model = masked_errors(r.own.image, r.rgb.image, r.rgb, spheres, basis);
    const std::vector<MaskedError> rgb = masked_errors(r.rgb.image, r.spectral.image, r.rgb, spheres, basis);
    const std::vector<MaskedError> total = masked_errors(r.own.image, r.spectral.image, r.rgb, spheres, basis);
    std::vector<SphereOrderError> out(spheres);
    for (std::size_t s = 0; s < spheres; ++s) out[s] = {model[s], rgb[s], total[s]};
    return out;
}

nlohmann::ordered_json masked_error_json(const MaskedError& e) {
    return {{"rmse", e.rmse}, {"de2000_mean", e.de2000_mean}, {"de2000_p95", e.de2000_p95}};
}

nlohmann::ordered_json bounce_orders_json(const std::vector<std::vector<SphereOrderError>>& orders,
                                          std::size_t sphere) {
    nlohmann::ordered_json out = nlohmann::ordered_json::array();
    for (std::size_t k = 0; k < orders.size(); ++k) {
        const SphereOrderError& e = orders[k].at(sphere);
        out.push_back({{"order", k + 1},
                       {"model", masked_error_json(e.model)},
                       {"rgb_vs_spectral", masked_error_json(e.rgb_vs_spectral)},
                       {"model_vs_spectral", masked_error_json(e.model_vs_spectral)}});
    }
    return out;
}

// Every sphere pixel as one mask.
ReferenceRender sphere_pixels_mask(const ReferenceRender& render) {
    ReferenceRender mask{render.image, render.sphere_id};
    for (int& id : mask.sphere_id) id = id >= 0 ? 0 : -1;
    return mask;
}

// The pixels whose mirror path reaches bounce `order` (it meets another sphere at every bounce before), as one mask.
ReferenceRender reaching_mask(const Scene& scene, const ReferenceRender& render, int order) {
    ReferenceRender mask{render.image, render.sphere_id};
    const CameraBasis basis = camera_basis(scene.camera, scene.width, scene.height);
    for (int row = 0; row < scene.height; ++row)
        for (int px = 0; px < scene.width; ++px) {
            int& id = mask.sphere_id[static_cast<std::size_t>(row) * scene.width + px];
            if (id < 0) continue;
            const int py = scene.height - 1 - row;
            const Vec3 d = camera_ray(basis, px, py, scene.width, scene.height);
            const SphereHit hit = nearest_sphere(scene.spheres, basis.position, d);
            id = mirror_path(scene.spheres, basis.position, d, hit, order).count == order ? 0 : -1;
        }
    return mask;
}

}  // namespace metalfit::glpreview
