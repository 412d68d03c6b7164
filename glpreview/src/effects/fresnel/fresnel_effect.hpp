// The Fresnel of each sphere as its shader evaluates it: the exact reference curve as a 1D RGB texture, or a libfit
// model's GLSL on its parameters (any number of them), chosen by type (ShaderBuilder::fresnel_model).
#pragma once

#include "glpreview/effects/effect.hpp"

namespace metalfit::glpreview {

const Effect& fresnel_effect();

}  // namespace metalfit::glpreview
