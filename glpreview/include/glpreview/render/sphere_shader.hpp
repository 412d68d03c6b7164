// The programs of a preview as builders (no GL): a sphere's shader assembled by the registered effects, and the
// environment's part of every program. The plan names the variants a scene compiles from these alone.
#pragma once

#include "glpreview/render/shader_builder.hpp"
#include "glpreview/scene/scene.hpp"

namespace metalfit::glpreview {

struct SphereFresnel;

// The sphere shader of one sphere: the environment, every registered effect's part, the camera and sphere.frag.
// `fresnel` resolves the model (null while planning: the variant's name only); `diagnostics`: the localization frame.
ShaderBuilder sphere_shader(const Scene& scene, const Sphere& sphere, const SphereFresnel* fresnel,
                            bool diagnostics = false);
// The environment's part of a program: what the effects add to it (Effect::declare_environment_program), its
// #define, environment.glsl and the equirect image's sampler.
void declare_environment(const Scene& scene, ShaderBuilder& builder);

}  // namespace metalfit::glpreview
