#include "caustics_effect.hpp"

#include <numbers>

#include "caustic_reference.hpp"
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
    // The rings' exact spectral Fresnel, resolved with the materials when a CPU reference is asked for; the photon map
    // is traced on the first cpu_surface_light (once, whichever thread comes first) and lights the room's faces with
    // albedo/π × E_caustic, as ENVIRONMENT_CAUSTICS does on the GPU.
    void resolve_materials(Scene& scene, FresnelLibrary& library) const override {
        resolve_caustic_spectra(scene, library);
    }
    bool lights_cpu_reference(const Scene& scene) const override {
        return has_caustics(scene) && scene.effects.find<CausticSpectra>();
    }
    RGB cpu_surface_light(const Scene& scene, const RGB& albedo, Vec3 p, Vec3 n) const override {
        const CausticMap* map = reference_caustic_map(scene);
        if (!map) return {0, 0, 0};
        const RGB e = map->irradiance_at(scene.environment.room, p, n);
        return (1.0 / std::numbers::pi) * RGB{albedo.r * e.r, albedo.g * e.g, albedo.b * e.b};
    }
};

}  // namespace

const Effect& caustics_effect() {
    static const CausticsEffect effect;
    return effect;
}

}  // namespace metalfit::glpreview
