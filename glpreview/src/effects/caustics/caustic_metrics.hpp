// metrics.json's "caustics" entry (schemas/preview-metrics.schema.json): the reference photon map's budget, per
// receiver its total power and brightest point, and per light and ring the closed form's focus with the distance of
// the floor's brightest point from it. measure_irradiance (photon_tracer.hpp) measures the same on any irradiance
// image (a GPU light map).
#pragma once

#include <vector>

#include <nlohmann/json.hpp>

#include "photon_tracer.hpp"

namespace metalfit::glpreview {

// The entry for a map of `scene` (its rings and lights); `luminance`: the weights the brightest point is found by.
nlohmann::json caustic_metrics_json(const Scene& scene, const CausticMap& map, const RGB& luminance);

// The GPU's light maps against the reference map, per room face that either lit (RoomLightMaps' layout: `faces`
// as read_room_light_maps gives them, `size` texels per edge): the GPU's power, its ratio to the reference's, the
// brightest texel and its distance from the reference's brightest point, the relative RMS of the irradiance over the
// face's texels; and the distance of the floor's brightest texel from each closed-form focus.
nlohmann::json gpu_caustic_metrics_json(const Scene& scene, const CausticMap& map,
                                        const std::vector<std::vector<float>>& faces, int size, const RGB& luminance);

}  // namespace metalfit::glpreview
