#include "indirect_settings.hpp"

namespace metalfit::glpreview {

IndirectSettings read_indirect_settings(const SceneReader& top) {
    IndirectSettings settings;
    const SceneReader r(top.at("indirect"), top.field("indirect"), top.file(),
                        {"paths", "clamp_distance", "evaluation_rate", "reference_samples", "light_map_size"});
    r.read("paths", settings.paths, 1, 1024);
    r.read("clamp_distance", settings.clamp_distance, 0, 10);
    r.read("evaluation_rate", settings.evaluation_rate, 0, 1);
    r.read("reference_samples", settings.reference_samples, 1, 65536);
    r.read("light_map_size", settings.light_map_size, 4, 1024);
    return settings;
}

}  // namespace metalfit::glpreview
