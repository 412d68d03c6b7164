// Test probe: reflection_lookup for given (x, R) pairs (with the impostor: and its distance reads), and the cube map's
// texel value at the lookup direction.
layout(local_size_x = 64) in;
layout(std430, binding = 0) readonly buffer Rays { vec4 rays[]; };  // x (relative to o), R: two vec4 per ray
layout(std430, binding = 1) writeonly buffer Results { vec4 results[]; };  // lookup direction + reads, cube texel
uniform int u_count;

void main() {
    int i = int(gl_GlobalInvocationID.x);
    if (i >= u_count) return;
    vec3 x = rays[2 * i].xyz, R = rays[2 * i + 1].xyz;
    vec3 lookup = reflection_lookup(x, R);
#if defined(REFLECTION_DISTANCE_IMPOSTOR)
    results[2 * i] = vec4(lookup, float(g_distance_lookups));
#else
    results[2 * i] = vec4(lookup, 0.0);
#endif
    results[2 * i + 1] = textureLod(u_env, lookup, 0.0);
}
