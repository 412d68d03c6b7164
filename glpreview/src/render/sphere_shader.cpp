#include "glpreview/render/sphere_shader.hpp"

#include "embedded_shaders.hpp"
#include "glpreview/effects/registry.hpp"
#include "glpreview/render/features.hpp"

namespace metalfit::glpreview {

void declare_environment(const Scene& scene, ShaderBuilder& builder) {
    // The effects' parts first: environment.glsl calls ENVIRONMENT_LIGHTING where one is defined.
    for (const Effect* effect : all_effects()) effect->declare_environment_program(scene, builder);
    builder.define(environment_define(scene.environment)).source(shader_text("environment.glsl"));
    if (scene.environment.type == EnvironmentType::equirect) builder.sampler("u_equirect");
}

ShaderBuilder sphere_shader(const Scene& scene, const Sphere& sphere, const SphereFresnel* fresnel, bool diagnostics) {
    ShaderBuilder builder("sphere");
    declare_environment(scene, builder);
    builder.radiance("mirror_radiance(p, R, mu)");  // the mirror, unless an effect gives the sphere another lobe
    const SphereShader shader{scene, sphere, fresnel, diagnostics};
    for (const Effect* effect : all_effects()) effect->declare_sphere(shader, builder);
    builder.source(shader_text("camera.glsl")).source(shader_text("sphere.frag"));
    return builder;
}

}  // namespace metalfit::glpreview
