// The registry of effects: the one list of what a preview can draw beyond a sphere mirroring its environment, in the
// order their GLSL is assembled and their passes are added. Adding an effect: a folder glpreview/src/effects/<effect>/
// (its code, its .glsl files, embedded by the build by themselves) and one line in src/effects/registry.cpp.
#pragma once

#include <span>

#include "glpreview/effects/effect.hpp"

namespace metalfit::glpreview {

std::span<const Effect* const> all_effects();
// Every effect's resolve_materials on `scene` (a preview's own copy): its objects' Fresnel through `library`, which
// must outlive the scene's use.
void resolve_effect_materials(Scene& scene, FresnelLibrary& library);

}  // namespace metalfit::glpreview
