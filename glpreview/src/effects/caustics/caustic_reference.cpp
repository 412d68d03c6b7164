#include "caustic_reference.hpp"

#include <algorithm>
#include <string>

#include "caustic_settings.hpp"
#include "glpreview/render/sphere_fresnel.hpp"

namespace metalfit::glpreview {

bool has_caustics(const Scene& scene) {
    const Rings* rings = scene.effects.find<Rings>();
    const Lights* lights = scene.effects.find<Lights>();
    return rings && !rings->rings.empty() && lights &&
           std::any_of(lights->lights.begin(), lights->lights.end(),
                       [](const Light& light) { return light.type != LightType::sphere; });
}

void resolve_caustic_spectra(Scene& scene, FresnelLibrary& library, bool always) {
    if (!has_caustics(scene)) return;
    const Outputs& o = scene.outputs;
    if (!always && !(o.reference || o.difference || o.metrics)) return;
    const Rings& rings = *scene.effects.find<Rings>();
    CausticSpectra spectra;
    for (std::size_t i = 0; i < rings.rings.size(); ++i)
        spectra.rings.push_back(std::make_shared<const SpectralFresnel>(
            library.material(rings.rings[i].surface(), "rings[" + std::to_string(i) + "]"), library.colorimetry()));
    spectra.uplift = std::make_shared<const RgbUplift>(library.colorimetry(), library.converter());
    scene.effects.set(std::move(spectra));
}

PhotonOptions caustic_photon_options(const Scene& scene) {
    PhotonOptions options;
    const CausticSettings settings =
        scene.effects.find<CausticSettings>() ? *scene.effects.find<CausticSettings>() : CausticSettings{};
    options.photons = settings.reference_photons;
    options.sigma = settings.filter_width;
    return options;
}

const CausticMap* reference_caustic_map(const Scene& scene) {
    const CausticSpectra* spectra = scene.effects.find<CausticSpectra>();
    if (!spectra || !has_caustics(scene)) return nullptr;
    std::call_once(spectra->lazy->once, [&] {
        PhotonFresnel fresnel;
        for (const auto& s : spectra->rings) fresnel.spectral.push_back(s.get());
        fresnel.uplift = spectra->uplift.get();
        spectra->lazy->map = trace_caustics(scene, *scene.effects.find<Rings>(), *scene.effects.find<Lights>(), fresnel,
                                            caustic_photon_options(scene));
    });
    return &spectra->lazy->map;
}

}  // namespace metalfit::glpreview
