// The registry of effects (effects/registry.hpp): one line per effect folder, in the order their GLSL is assembled
// and their passes are added (the frame's inputs before the beauty frame, the outputs after it).
#include "glpreview/effects/registry.hpp"

#include <array>
#include <vector>

#include "caustics/caustics_effect.hpp"
#include "environment/environment_effect.hpp"
#include "fit_error/fit_error_effect.hpp"
#include "fresnel/fresnel_effect.hpp"
#include "glossy_localized/glossy_localized_effect.hpp"
#include "glossy_prefiltered/glossy_prefiltered_effect.hpp"
#include "indirect/indirect_effect.hpp"
#include "interreflections/interreflections_effect.hpp"
#include "lights/lights_effect.hpp"
#include "localization_diagnostics/localization_diagnostics_effect.hpp"
#include "metrics/metrics_effect.hpp"
#include "reference/reference_effect.hpp"
#include "reflection/reflection_effect.hpp"
#include "rim/rim_effect.hpp"
#include "rings/rings_effect.hpp"

namespace metalfit::glpreview {

std::span<const Effect* const> all_effects() {
    static const std::array<const Effect*, 15> effects{
        &rings_effect(),     // first: the room's rings are in every program that reads the environment
        &lights_effect(),    // before the capture of the environment: it reads its shadow maps
        &caustics_effect(),  // after the lights, before the capture: it reads its light maps
        &indirect_effect(),  // after the lights and caustics: its CPU reference gathers their light
        &environment_effect(),
        &reflection_effect(),
        &fresnel_effect(),
        &glossy_prefiltered_effect(),
        &glossy_localized_effect(),
        &interreflections_effect(),  // after every frame input its maps' sphere draws read
        &reference_effect(),
        &localization_diagnostics_effect(),  // after the lobes: the localization frame replaces every lobe
        &fit_error_effect(),                 // after the reference: its error view reads it
        &metrics_effect(),                   // after the reference and the localization frame it reads
        &rim_effect(),                       // after fit-error: it reads the frame with the exact curves
    };
    return effects;
}

void resolve_effect_materials(Scene& scene, FresnelLibrary& library) {
    for (const Effect* effect : all_effects()) effect->resolve_materials(scene, library);
}

std::span<const SceneKeys* const> scene_key_readers() {
    static const std::vector<const SceneKeys*> readers(all_effects().begin(), all_effects().end());
    return readers;
}

}  // namespace metalfit::glpreview
