// A rough sphere, thesis ch. 5 (docs/scene.md, "Rough spheres (exact rules)"): the downsampled cube's 6 M² texels as area lights with their
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
vec3 localized_glossy(vec3 x, vec3 N, vec3 V, float mu) {
    int M = textureSize(u_area_radiance, 0).y;
    const int k = LOCALIZED_SUBDIVISIONS;
    float a = u_roughness * u_roughness, a2 = a * a;
    float lambda_v = ggx_smith_lambda(mu, a2);
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
                       (ggx_lobe(N, H, l, a2, lambda_v, n_v) * dw);
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
                        light_sum += fresnel(clamp(dot(V, H), 0.0, 1.0)) * (ggx_lobe(N, H, l, a2, lambda_v, n_v) * dw);
                    }
                float scale = position.a / weights;
                total += scale * light_total;
                sum += texelFetch(u_area_radiance, texel, 0).rgb * (scale * light_sum);
#endif
            }
    return sum * (4.0 * GGX_PI / total);
}
