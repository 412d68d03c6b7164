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

#if defined(GLOSSY_LOCALIZED)
// A rough sphere, thesis ch. 5 (FORMULAS.md §6): the downsampled cube's 6 M² texels as area lights with their
// average radiance L_i and average position y_i; reflected radiance Σ L_i f_r(ω_i, ω_o) cos θ_i Δω_i(x) with the GGX
// BRDF and this sphere's Fresnel at the microfacet angle. Departures from the thesis's sum (docs/decisions.md,
// measured in a white furnace): the light's solid angle from x is its texel's exact solid angle from o carried to
// x as a patch facing o at distance r = |y_i| (Δω · r² / r*² · cos γ), not the point-to-disc Δω*, so that the lights
// tile the sphere of directions; the solid angles are renormalised to sum to 4π; and where the lobe is narrower
// than a light, each light is split into k × k sub-lights (k = LOCALIZED_SUBDIVISIONS; same L_i, in the directions
// of the sub-rectangles at the light's distance), which also integrates the BRDF over the light and splits the
// lights that straddle the horizon. With k = 1 the sample point is y_i itself.
uniform sampler2D u_area_radiance;  // 6M × M: average radiance
uniform sampler2D u_area_position;  // 6M × M: average position relative to the reference point; a: Δω_i from o
uniform float u_roughness;
const float LOCALIZED_PI = 3.14159265358979;
float smith_lambda(float cos_t, float a2) {
    float c2 = max(cos_t * cos_t, 1e-12);
    return 0.5 * (-1.0 + sqrt(1.0 + a2 * (1.0 - c2) / c2));
}
// f_r cos θ_i for light direction l and half vector H, without the Fresnel: D G2 / (4 n·v).
float lobe(vec3 N, vec3 H, vec3 l, float a2, float lambda_v, float n_v) {
    float n_h = dot(N, H);
    float d = n_h * n_h * (a2 - 1.0) + 1.0;
    float D = a2 / (LOCALIZED_PI * d * d);
    float G2 = 1.0 / (1.0 + lambda_v + smith_lambda(dot(N, l), a2));
    return D * G2 / (4.0 * n_v);
}
vec3 localized_glossy(vec3 x, vec3 N, vec3 V, float mu) {
    int M = textureSize(u_area_radiance, 0).y;
    const int k = LOCALIZED_SUBDIVISIONS;
    float a = u_roughness * u_roughness, a2 = a * a;
    float lambda_v = smith_lambda(mu, a2);
    float n_v = max(mu, 1e-4);
    float step_st = 2.0 / float(M), step_sub = step_st / float(k);
    vec3 sum = vec3(0.0);
    float total = 0.0;  // Σ Δω_i(x) over all lights, visible or not
    for (int face = 0; face < 6; ++face)
        for (int j = 0; j < M; ++j)
            for (int i = 0; i < M; ++i) {
                ivec2 texel = ivec2(face * M + i, j);
                vec4 position = texelFetch(u_area_position, texel, 0);
                vec3 y = position.xyz;
                float r = length(y);
                // Each sample is a patch facing o at the light's distance r: from x it subtends its solid angle from
                // o times r² / r*² · cos γ. With k = 1 the light itself, p = y_i, with Δω_i (position.a).
#if LOCALIZED_SUBDIVISIONS == 1
                vec3 to_light = y - x;
                float r_star2 = dot(to_light, to_light);
                vec3 l = to_light * inversesqrt(r_star2);
                float dw = position.a * (r * r / r_star2) * max(dot(y, l) / r, 0.0);
                total += dw;
                if (dot(N, l) <= 0.0) continue;
                vec3 H = normalize(V + l);
                sum += texelFetch(u_area_radiance, texel, 0).rgb * fresnel(clamp(dot(V, H), 0.0, 1.0)) *
                       (lobe(N, H, l, a2, lambda_v, n_v) * dw);
#else
                // k × k sub-lights: the sub-rectangles' centre directions d at the light's distance, p = r d; their
                // solid angles from o in proportion to 1 / |c|³ (c the unnormalised direction; equal areas in face
                // coordinates), scaled to sum to the light's Δω_i.
                float s0 = -1.0 + float(i) * step_st, t0 = -1.0 + float(j) * step_st;
                vec3 light_sum = vec3(0.0);
                float light_total = 0.0, weights = 0.0;
                for (int sj = 0; sj < k; ++sj)
                    for (int si = 0; si < k; ++si) {
                        vec3 c = cube_direction(face, s0 + (float(si) + 0.5) * step_sub, t0 + (float(sj) + 0.5) * step_sub);
                        float inverse_length = inversesqrt(dot(c, c));
                        vec3 d = c * inverse_length;
                        float w = inverse_length * inverse_length * inverse_length;
                        weights += w;
                        vec3 to_light = r * d - x;
                        float r_star2 = dot(to_light, to_light);
                        vec3 l = to_light * inversesqrt(r_star2);
                        float dw = w * (r * r / r_star2) * max(dot(d, l), 0.0);
                        light_total += dw;
                        if (dot(N, l) <= 0.0) continue;
                        vec3 H = normalize(V + l);
                        light_sum += fresnel(clamp(dot(V, H), 0.0, 1.0)) * (lobe(N, H, l, a2, lambda_v, n_v) * dw);
                    }
                float scale = position.a / weights;
                total += scale * light_total;
                sum += texelFetch(u_area_radiance, texel, 0).rgb * (scale * light_sum);
#endif
            }
    return sum * (4.0 * LOCALIZED_PI / total);
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
#if defined(GLOSSY_LOCALIZED)
    out_color = vec4(localized_glossy(p - u_reference, N, -d, mu), 1.0);
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
