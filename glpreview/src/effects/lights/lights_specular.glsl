// The direct specular of rough spheres from the scene's lights (lights effect; lights.glsl and ggx.glsl come first).
// The sphere's Fresnel is defined after this file.
vec3 fresnel(float mu);

// The direct specular of a rough sphere at p (unit normal N, unit V towards the viewer): per light
// F(v·h) D(h) G2(l, v) / (4 n·v n·l) · E n·l · shadow. Sphere lights by a representative point (Karis 2013, "Real
// Shading in Unreal Engine 4"): l towards the light's point nearest the mirror ray, D normalised by (α / α')² with
// α' = α + r / (2 d), so that one GGX evaluation per light keeps the highlight's size and energy.
vec3 lights_specular(vec3 p, vec3 N, vec3 V, float roughness) {
    float a = max(roughness * roughness, 1e-3);
    float a2 = a * a;
    float n_v = max(dot(N, V), 1e-4);
    float lambda_v = ggx_smith_lambda(n_v, a2);
    vec3 R = reflect(-V, N);
    vec3 sum = vec3(0.0);
    for (int i = 0; i < u_light_count; ++i) {
        vec3 l, E;
        float dist;
        lights_at(i, p, l, E, dist);
        float normalisation = 1.0;
        if (u_light_type[i] == 3) {
            vec3 to = u_light_position[i] - p;
            vec3 centre_to_ray = dot(to, R) * R - to;
            vec3 nearest = to + centre_to_ray * clamp(u_light_radius[i] / max(length(centre_to_ray), 1e-9), 0.0, 1.0);
            l = normalize(nearest);
            float a_wide = clamp(a + u_light_radius[i] / (2.0 * dist), 0.0, 1.0);
            normalisation = (a / a_wide) * (a / a_wide);
        }
        float n_l = dot(N, l);
        if (n_l <= 0.0) continue;
        vec3 H = normalize(V + l);  // n·h > 0: n·v and n·l are
        sum += fresnel(clamp(dot(V, H), 0.0, 1.0)) * E *
               (ggx_lobe(N, H, l, a2, lambda_v, n_v) * normalisation * lights_shadow(i, p, N));
    }
    return sum;
}
