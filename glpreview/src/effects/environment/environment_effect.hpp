// The environment every sphere reflects: a procedural room, a sphere room or an equirect image (at infinity, or on
// its box or sphere proxy), loaded (load-equirect) and captured by GL into a cube map around the reference point
// (capture-environment); its uniforms in every program that reads environment.glsl. The passes are declared in
// render/preview_passes.hpp (the sheet adds them too).
#pragma once

#include "glpreview/effects/effect.hpp"

namespace metalfit::glpreview {

const Effect& environment_effect();

}  // namespace metalfit::glpreview
