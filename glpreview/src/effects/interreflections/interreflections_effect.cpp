#include "interreflections_effect.hpp"

#include <string>

#include "bounces.hpp"

namespace metalfit::glpreview {

int max_bounces(const Scene& scene) {
    const Interreflections* settings = scene.effects.find<Interreflections>();
    return settings ? settings->max_bounces : 1;
}

namespace {

class InterreflectionsEffect final : public Effect {
public:
    std::string_view name() const override { return "interreflections"; }

    std::vector<const char*> scene_keys() const override { return {"max_bounces"}; }
    void read_scene(const SceneReader& top, Scene& scene) const override {
        if (!top.has("max_bounces")) return;
        Interreflections settings;
        top.read("max_bounces", settings.max_bounces, 1, kMaxBounces);
        scene.effects.set(settings);
    }
    // Spheres that reflect each other must not overlap: a ray leaving one would start inside another.
    void check_scene(const SceneReader& top, const Scene& scene) const override {
        if (max_bounces(scene) <= 1) return;
        for (std::size_t j = 0; j < scene.spheres.size(); ++j)
            for (std::size_t i = 0; i < j; ++i) {
                const Sphere& a = scene.spheres[i];
                const Sphere& b = scene.spheres[j];
                if (length(b.center - a.center) < a.radius + b.radius)
                    top.fail(top.field("spheres[" + std::to_string(j) + "]"),
                             "overlaps spheres[" + std::to_string(i) +
                                 "]: spheres that reflect each other (max_bounces > 1) must not overlap");
            }
    }
};

}  // namespace

const Effect& interreflections_effect() {
    static const InterreflectionsEffect effect;
    return effect;
}

}  // namespace metalfit::glpreview
