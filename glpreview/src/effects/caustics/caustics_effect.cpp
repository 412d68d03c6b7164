#include "caustics_effect.hpp"

#include "caustic_settings.hpp"

namespace metalfit::glpreview {
namespace {

class CausticsEffect final : public Effect {
public:
    std::string_view name() const override { return "caustics"; }

    std::vector<const char*> scene_keys() const override { return {"caustics"}; }
    void read_scene(const SceneReader& top, Scene& scene) const override {
        if (top.has("caustics")) scene.effects.set(read_caustic_settings(top));
    }

    // --- The CPU reference (the photon tracer) ---
};

}  // namespace

const Effect& caustics_effect() {
    static const CausticsEffect effect;
    return effect;
}

}  // namespace metalfit::glpreview
