// The caustics in the CPU references: each ring's exact spectral Fresnel and the RGB → spectrum uplift, resolved
// with the materials (Effect::resolve_materials), and the photon map of the scene (photon_tracer.hpp), traced once
// on first use and shared by every thread of the references.
#pragma once

#include <memory>
#include <mutex>
#include <vector>

#include "photon_tracer.hpp"

namespace metalfit::glpreview {

class FresnelLibrary;

// Set on the scene by resolve_caustic_spectra (Scene::effects): immutable but for the map it traces once.
struct CausticSpectra {
    std::vector<std::shared_ptr<const SpectralFresnel>> rings;  // per ring
    std::shared_ptr<const RgbUplift> uplift;
    struct Lazy {
        std::once_flag once;
        CausticMap map;
    };
    std::shared_ptr<Lazy> lazy = std::make_shared<Lazy>();
};

// Whether the scene throws caustics the reference traces: a ring and a light other than a sphere light.
bool has_caustics(const Scene& scene);
// Resolves the rings' spectral Fresnel into the scene (when it has caustics and asks for a CPU reference or
// `always`). Throws InputError naming rings[i] as FresnelLibrary does.
void resolve_caustic_spectra(Scene& scene, FresnelLibrary& library, bool always = false);
// The scene's photon map with the exact spectral Fresnel (caustics.reference_photons per light and ring, σ =
// caustics.filter_width), traced on the first call; null when the scene has no caustics or was not resolved.
const CausticMap* reference_caustic_map(const Scene& scene);
// The photon options of a scene (its caustics key, or the defaults).
PhotonOptions caustic_photon_options(const Scene& scene);

}  // namespace metalfit::glpreview
