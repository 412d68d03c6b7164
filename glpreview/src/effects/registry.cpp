// The registry of effects (effects/registry.hpp): one line per effect folder, in the order their GLSL is assembled
// and their passes are added.
#include "glpreview/effects/registry.hpp"

#include <array>

#include "fresnel/fresnel_effect.hpp"
#include "glossy_localized/glossy_localized_effect.hpp"
#include "glossy_prefiltered/glossy_prefiltered_effect.hpp"
#include "localization_diagnostics/localization_diagnostics_effect.hpp"
#include "reflection/reflection_effect.hpp"

namespace metalfit::glpreview {

std::span<const Effect* const> all_effects() {
    static const std::array<const Effect*, 5> effects{
        &reflection_effect(),
        &fresnel_effect(),
        &glossy_prefiltered_effect(),
        &glossy_localized_effect(),
        &localization_diagnostics_effect(),  // last: the localization frame replaces every lobe
    };
    return effects;
}

}  // namespace metalfit::glpreview
