#include "caustic_settings.hpp"

#include <string>

namespace metalfit::glpreview {

CausticSettings read_caustic_settings(const SceneReader& top) {
    CausticSettings settings;
    const SceneReader r(top.at("caustics"), top.field("caustics"), top.file(),
                        {"map_size", "filter_width", "light_map_size", "reference_photons"});
    // A map is a render target like the image: the same edge limit.
    r.read("map_size", settings.map_size, 4, kMaxImageEdge);
    if (r.has("filter_width") && r.at("filter_width").is_number() && !(r.at("filter_width").get<double>() > 0))
        r.fail(r.field("filter_width"), "must be > 0");
    r.read("filter_width", settings.filter_width, 1e-4, 1.0);
    r.read("light_map_size", settings.light_map_size, 16, 4096);
    r.read("reference_photons", settings.reference_photons, 1000, 1 << 26);
    return settings;
}

}  // namespace metalfit::glpreview
