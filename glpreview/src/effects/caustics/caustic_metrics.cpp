#include "caustic_metrics.hpp"

#include <cmath>

#include "caustic_closed_form.hpp"
#include "glpreview/render/room_light_maps.hpp"

namespace metalfit::glpreview {
namespace {

nlohmann::json rgb_json(const RGB& c) { return {c.r, c.g, c.b}; }

// A receiver's (u, v) as a point of the room.
Vec3 receiver_point(const Room& room, Receiver receiver, double u, double v) {
    switch (receiver) {
        case Receiver::floor: return {u, room.min.y, v};
        case Receiver::ceiling: return {u, room.max.y, v};
        case Receiver::wall_x_min: return {room.min.x, v, u};
        case Receiver::wall_x_max: return {room.max.x, v, u};
        case Receiver::wall_z_min: return {u, v, room.min.z};
        case Receiver::wall_z_max: return {u, v, room.max.z};
    }
    return {};
}

}  // namespace

nlohmann::json caustic_metrics_json(const Scene& scene, const CausticMap& map, const RGB& luminance) {
    const PhotonBudget& b = map.budget();
    nlohmann::json j;
    j["filter_width"] = map.sigma();
    j["photons_traced"] = b.traced;
    j["photons_on_rings"] = b.hits;
    j["photons_reflected_again"] = b.multiple;
    j["intercepted"] = rgb_json(b.intercepted);
    j["reflected"] = rgb_json(b.reflected);
    j["deposited"] = rgb_json(b.deposited);
    j["deposited_after_several_reflections"] = rgb_json(b.deposited_multiple);
    j["absorbed"] = rgb_json(b.absorbed);
    j["receivers"] = nlohmann::json::array();
    const Room& room = scene.environment.room;
    IrradiancePeak floor_peak;
    for (int r = 0; r < kReceivers; ++r) {
        const auto receiver = static_cast<Receiver>(r);
        if (map.receiver(receiver).photons.empty()) continue;
        const IrradiancePeak peak = measure_receiver(map, receiver, luminance);
        if (receiver == Receiver::floor) floor_peak = peak;
        const Vec3 at = receiver_point(room, receiver, peak.u, peak.v);
        j["receivers"].push_back({{"receiver", receiver_name(receiver)},
                                  {"photons", map.receiver(receiver).photons.size()},
                                  {"power", rgb_json(map.receiver(receiver).power)},
                                  {"peak_position", {at.x, at.y, at.z}},
                                  {"peak_irradiance", rgb_json(peak.irradiance)}});
    }
    j["focus"] = nlohmann::json::array();
    const Rings& rings = *scene.effects.find<Rings>();
    const Lights& lights = *scene.effects.find<Lights>();
    const bool floor_lit = !map.receiver(Receiver::floor).photons.empty();
    for (std::size_t l = 0; l < lights.lights.size(); ++l)
        for (std::size_t r = 0; r < rings.rings.size(); ++r) {
            std::string why;
            nlohmann::json e{{"light", l}, {"ring", r}};
            if (const std::optional<CausticFocus> focus = caustic_focus(rings.rings[r], lights.lights[l], &why)) {
                e["form"] = focus->form;
                e["point"] = {focus->point.x, focus->point.y, focus->point.z};
                e["wall_height"] = focus->wall_height;
                e["floor_peak_distance"] =
                    floor_lit ? nlohmann::json(std::hypot(floor_peak.u - focus->point.x, floor_peak.v - focus->point.z))
                              : nlohmann::json(nullptr);
            } else {
                e["none"] = why;
            }
            j["focus"].push_back(e);
        }
    return j;
}

nlohmann::json gpu_caustic_metrics_json(const Scene& scene, const CausticMap& map,
                                        const std::vector<std::vector<float>>& faces, int size, const RGB& luminance) {
    const Room& room = scene.environment.room;
    const auto weigh = [&luminance](const RGB& c) { return luminance.r * c.r + luminance.g * c.g + luminance.b * c.b; };
    nlohmann::json j;
    j["light_map_size"] = size;
    j["receivers"] = nlohmann::json::array();
    static const char* const kFaceNames[6] = {"wall_x_min", "wall_x_max", "floor",
                                              "ceiling",    "wall_z_min", "wall_z_max"};
    Vec3 floor_peak;
    bool floor_lit = false;
    for (int face = 0; face < 6; ++face) {
        const RoomFace f = room_face(room, face);
        const std::vector<float>& texels = faces.at(static_cast<std::size_t>(face));
        RGB gpu_power{0, 0, 0}, reference_power{0, 0, 0};
        double deviation = 0, norm = 0, best_gpu = -1, best_reference = -1;
        Vec3 gpu_peak, reference_peak;
        const double area = f.texel_area(size);
        for (int y = 0; y < size; ++y)
            for (int x = 0; x < size; ++x) {
                const Vec3 p = f.origin + ((x + 0.5) / size) * f.u + ((y + 0.5) / size) * f.v;
                const std::size_t t = 3 * (static_cast<std::size_t>(y) * size + x);
                const RGB gpu{texels[t], texels[t + 1], texels[t + 2]};
                const RGB reference = map.irradiance_at(room, p, f.normal);
                gpu_power = gpu_power + area * gpu;
                reference_power = reference_power + area * reference;
                const double g = weigh(gpu), r = weigh(reference);
                deviation += (g - r) * (g - r);
                norm += r * r;
                if (g > best_gpu) {
                    best_gpu = g;
                    gpu_peak = p;
                }
                if (r > best_reference) {
                    best_reference = r;
                    reference_peak = p;
                }
            }
        if (!(weigh(gpu_power) > 0) && !(weigh(reference_power) > 0)) continue;
        if (face == 2) {
            floor_peak = gpu_peak;
            floor_lit = weigh(gpu_power) > 0;
        }
        j["receivers"].push_back(
            {{"receiver", kFaceNames[face]},
             {"power", rgb_json(gpu_power)},
             {"reference_power_on_texels", rgb_json(reference_power)},
             {"power_ratio", weigh(reference_power) > 0 ? nlohmann::json(weigh(gpu_power) / weigh(reference_power))
                                                        : nlohmann::json(nullptr)},
             {"peak_position", {gpu_peak.x, gpu_peak.y, gpu_peak.z}},
             {"peak_distance_to_reference", length(gpu_peak - reference_peak)},
             {"irradiance_rel_rms", norm > 0 ? nlohmann::json(std::sqrt(deviation / norm)) : nlohmann::json(nullptr)}});
    }
    j["focus"] = nlohmann::json::array();
    const Rings& rings = *scene.effects.find<Rings>();
    const Lights& lights = *scene.effects.find<Lights>();
    for (std::size_t l = 0; l < lights.lights.size(); ++l)
        for (std::size_t r = 0; r < rings.rings.size(); ++r)
            if (const std::optional<CausticFocus> focus = caustic_focus(rings.rings[r], lights.lights[l], nullptr))
                j["focus"].push_back(
                    {{"light", l},
                     {"ring", r},
                     {"floor_peak_distance", floor_lit ? nlohmann::json(std::hypot(floor_peak.x - focus->point.x,
                                                                                   floor_peak.z - focus->point.z))
                                                       : nlohmann::json(nullptr)}});
    return j;
}

}  // namespace metalfit::glpreview
