// One mirror sphere: ray-cast against the sphere, reflect, find the reflected radiance (reflection_lookup into the
// captured cube map, or the image at infinity), multiply by the Fresnel of μ = cos θ.
// FRESNEL_REFERENCE: the exact curve R_c(μ) from libfit as a 1D RGB texture; otherwise FRESNEL_CALL is a libfit model
// function (its GLSL is libfit's single definition, prepended). LOCALIZATION_DIAGNOSTICS writes the impostor's
// steps and final |ρ − 1| instead of radiance.
uniform vec3 u_sphere_center;
uniform float u_sphere_radius;
layout(location = 0) out vec4 out_color;

#if defined(FRESNEL_REFERENCE)
uniform sampler1D u_fresnel_lut;  // texel i holds R_c(i / (n − 1))
vec3 fresnel(float mu) {
    float n = float(textureSize(u_fresnel_lut, 0));
    return textureLod(u_fresnel_lut, (mu * (n - 1.0) + 0.5) / n, 0.0).rgb;
}
#else
uniform vec3 u_param[4];  // the model's parameters, one vec3 (R, G, B) each, in libfit's order
vec3 fresnel(float mu) { return FRESNEL_CALL; }
#endif

#if defined(GLOSSY_PREFILTERED)
// A rough sphere, split sum: the prefiltered radiance along the localized mirror lookup, at the mip level of its
// roughness, times the DFG table of this sphere's own Fresnel over (μ, roughness).
uniform samplerCube u_prefiltered;
uniform sampler2D u_dfg;  // texel (i, j): μ = i / (width − 1), roughness = j / (height − 1)
uniform float u_roughness;
uniform float u_prefiltered_levels;
vec3 dfg(float mu, float roughness) {
    vec2 size = vec2(textureSize(u_dfg, 0));
    return textureLod(u_dfg, (vec2(mu, roughness) * (size - 1.0) + 0.5) / size, 0.0).rgb;
}
#endif

void main() {
    vec3 d = camera_ray(gl_FragCoord.xy);
    vec3 oc = u_camera_position - u_sphere_center;
    float b = dot(oc, d);
    float h = b * b - (dot(oc, oc) - u_sphere_radius * u_sphere_radius);
    if (h < 0.0) discard;
    float t = -b - sqrt(h);
    if (t <= 0.0) discard;
    vec3 p = u_camera_position + t * d;
    vec3 N = (p - u_sphere_center) / u_sphere_radius;
    float mu = clamp(-dot(d, N), 0.0, 1.0);
    vec3 R = reflect(d, N);
#if defined(LOCALIZATION_DIAGNOSTICS)
    // Why the localization is where it is: the refinement steps taken and |ρ − 1| at the lookup point; b = 1 marks
    // the impostor's pixels.
#if defined(REFLECTION_DISTANCE_IMPOSTOR)
    vec3 lookup = reflection_lookup(p - u_reference, R);
    out_color = vec4(float(g_iterations_taken), abs(impostor_rho(lookup) - 1.0), 1.0, 1.0);
#else
    out_color = vec4(0.0, 0.0, 0.0, 1.0);
#endif
    gl_FragDepth = t / (t + 1.0);
    return;
#endif
#if defined(GLOSSY_PREFILTERED)
    vec3 glossy = textureLod(u_prefiltered, reflection_lookup(p - u_reference, R), u_roughness * (u_prefiltered_levels - 1.0)).rgb;
    out_color = vec4(dfg(mu, u_roughness) * glossy, 1.0);
    gl_FragDepth = t / (t + 1.0);
    return;
#endif
#if defined(ENV_EQUIRECT)
    vec3 L = environment_trace(p, R).rgb;  // at infinity: the direction alone
#else
    vec3 L = textureLod(u_env, reflection_lookup(p - u_reference, R), 0.0).rgb;
#endif
    out_color = vec4(fresnel(mu) * L, 1.0);
    gl_FragDepth = t / (t + 1.0);
}
