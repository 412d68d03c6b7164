#include "caustic_metrics.hpp"

#include <cmath>

#include "caustic_closed_form.hpp"

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

}  // namespace metalfit::glpreview
