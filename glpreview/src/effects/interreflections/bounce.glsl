// Inter-reflections (the interreflections effect; docs/preview.md, "Inter-reflections on the GPU"): a mirror sphere's
// reflected ray is searched in the front layer of the sphere's own distance map (the distance impostor of
// reflection.glsl, in layer g_impostor_layer of u_impostor_layers). Where the map shows another mirror sphere and the
// point found lies on it, the ray reflects there (the normal of that sphere at the point, its Fresnel at this
// bounce's μ) and the search goes on in that sphere's map, up to MAX_BOUNCES reflections along the path; where it
// shows the room or a rough sphere (stored as the radiance it sends to the map's centre) and the point lies on it,
// that radiance ends the path. A point on neither (the search stopped at the edge of a sphere the ray passes behind,
// which one layer cannot resolve) is searched again in the back layer, the room alone. The last reflected ray reads
// the room's cube from its reference point, as a one-bounce mirror does (no sphere is seen after the last
// reflection).
uniform samplerCubeArray u_bounce_hits;  // xyz: the normal of the mirror sphere seen; w: its index + 1 (0: none)
uniform sampler2D u_bounce_fresnel;      // row j: sphere j's Fresnel over μ ∈ [0, 1] (its LUT or its model)
uniform sampler2D u_bounce_spheres;      // column j: sphere j's centre, w its layer (−1: none); row 1: its radius
uniform int u_bounce_back;               // layer L's back layer is L + u_bounce_back
uniform int u_bounce_sphere;             // the sphere drawn

// Whether the point p, where the search stopped, lies on sphere j: within 3 % of its radius, since the bilinear
// distance of a sphere seen near its silhouette from the map's centre departs from the sphere by up to a few per cent
// of r (measured: glpreview --bench-interreflections; 1 % rejects true hits there). A point farther off is a ray
// passing behind the sphere.
bool on_sphere(vec3 p, int j) {
    vec3 c = texelFetch(u_bounce_spheres, ivec2(j, 0), 0).xyz;
    float r = texelFetch(u_bounce_spheres, ivec2(j, 1), 0).x;
    return abs(length(p - c) - r) < 3e-2 * r;
}

vec3 bounce_fresnel(int sphere, float mu) {
    vec2 size = vec2(textureSize(u_bounce_fresnel, 0));
    return texture(u_bounce_fresnel, vec2((mu * (size.x - 1.0) + 0.5) / size.x, (float(sphere) + 0.5) / size.y)).rgb;
}

vec3 bounce_radiance(vec3 p, vec3 R) {
    vec3 throughput = vec3(1.0);
    vec4 here = texelFetch(u_bounce_spheres, ivec2(u_bounce_sphere, 0), 0);
    for (int k = 1; k < MAX_BOUNCES && here.w > -0.5; ++k) {
        int layer = int(floor(here.w + 0.5));
        g_impostor_layer = layer;
        vec3 direction = reflection_lookup(p - here.xyz, R);
        vec4 seen = textureLod(u_bounce_hits, vec4(direction, float(layer)), 0.0);
        vec4 texel = textureLod(u_impostor_layers, vec4(direction, float(layer)), 0.0);
        int index = int(floor(abs(seen.w) + 0.5)) - 1;
        vec3 point = here.xyz + direction;  // where the search stopped (|ρ − 1| < TOLERANCE when it converged)
        bool resolved = index >= 0 ? on_sphere(point, index)
                                   : abs(length(direction) / texel.a - 1.0) < 1e-2;
        if (!resolved) {  // behind the edge of a sphere: the room alone
            g_impostor_layer = layer + u_bounce_back;
            direction = reflection_lookup(p - here.xyz, R);
            g_impostor_layer = -1;
            return throughput * textureLod(u_impostor_layers, vec4(direction, float(layer + u_bounce_back)), 0.0).rgb;
        }
        g_impostor_layer = -1;
        if (index < 0 || seen.w < 0.0) return throughput * texel.rgb;  // the room, or a rough sphere's radiance
        p = point;
        here = texelFetch(u_bounce_spheres, ivec2(index, 0), 0);
        vec3 N = normalize(p - here.xyz);
        throughput *= bounce_fresnel(index, clamp(-dot(R, N), 0.0, 1.0));
        R = reflect(R, N);
    }
    return throughput * textureLod(u_env, reflection_lookup(p - u_reference, R), 0.0).rgb;
}
