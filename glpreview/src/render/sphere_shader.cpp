#include "glpreview/render/sphere_shader.hpp"

#include "embedded_shaders.hpp"
#include "glpreview/effects/registry.hpp"
#include "glpreview/graph/features.hpp"

namespace metalfit::glpreview {

void declare_environment(const Environment& environment, ShaderBuilder& builder) {
    builder.define(environment_define(environment)).source(shader_text("environment.glsl"));
    if (environment.type == EnvironmentType::equirect) builder.sampler("u_equirect");
}

ShaderBuilder sphere_shader(const Scene& scene, const Sphere& sphere, const SphereFresnel* fresnel, bool diagnostics) {
    ShaderBuilder builder("sphere");
    declare_environment(scene.environment, builder);
    builder.radiance("mirror_radiance(p, R, mu)");  // the mirror, unless an effect gives the sphere another lobe
    const SphereShader shader{scene, sphere, fresnel, diagnostics};
    for (const Effect* effect : all_effects()) effect->declare_sphere(shader, builder);
    builder.source(shader_text("camera.glsl")).source(shader_text("sphere.frag"));
    return builder;
}

}  // namespace metalfit::glpreview
