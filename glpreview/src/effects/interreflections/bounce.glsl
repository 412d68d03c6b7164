// Inter-reflections (the interreflections effect; docs/preview.md, "Inter-reflections"): a mirror sphere's reflected
// ray is searched in the sphere's own distance map (the distance impostor of reflection.glsl, in layer
// g_impostor_layer of u_impostor_layers). Where the map shows another mirror sphere, the ray reflects there (that
// sphere's normal from the map, its Fresnel at this bounce's μ) and the search goes on in that sphere's map, up to
// MAX_BOUNCES reflections along the path; where it shows the room (or a rough sphere, stored as the radiance it sends
// to the map's centre) that radiance ends the path. The last reflected ray reads the room's cube from its reference
// point, as a one-bounce mirror does (spheres are not seen after the last reflection).
uniform samplerCubeArray u_bounce_hits;  // xyz: the normal of the mirror sphere seen; w: its index + 1 (0: none)
uniform sampler2D u_bounce_fresnel;      // row j: sphere j's Fresnel over μ ∈ [0, 1] (its LUT or its model)
uniform sampler2D u_bounce_spheres;      // texel j: sphere j's centre; w: its layer in the maps (−1: none)
uniform int u_bounce_sphere;             // the sphere drawn

vec3 bounce_fresnel(int sphere, float mu) {
    vec2 size = vec2(textureSize(u_bounce_fresnel, 0));
    return texture(u_bounce_fresnel, vec2((mu * (size.x - 1.0) + 0.5) / size.x, (float(sphere) + 0.5) / size.y)).rgb;
}

vec3 bounce_radiance(vec3 p, vec3 R) {
    vec3 throughput = vec3(1.0);
    vec4 here = texelFetch(u_bounce_spheres, ivec2(u_bounce_sphere, 0), 0);
    for (int k = 1; k < MAX_BOUNCES && here.w > -0.5; ++k) {
        float layer = floor(here.w + 0.5);
        g_impostor_layer = int(layer);
        vec3 direction = reflection_lookup(p - here.xyz, R);
        g_impostor_layer = -1;
        vec4 seen = textureLod(u_bounce_hits, vec4(direction, layer), 0.0);
        vec4 texel = textureLod(u_impostor_layers, vec4(direction, layer), 0.0);
        int hit = int(floor(seen.w + 0.5)) - 1;
        if (hit < 0) return throughput * texel.rgb;
        vec3 N = normalize(seen.xyz);
        p = here.xyz + normalize(direction) * texel.a;  // on the sphere seen
        throughput *= bounce_fresnel(hit, clamp(-dot(R, N), 0.0, 1.0));
        R = reflect(R, N);
        here = texelFetch(u_bounce_spheres, ivec2(hit, 0), 0);
    }
    return throughput * textureLod(u_env, reflection_lookup(p - u_reference, R), 0.0).rgb;
}
