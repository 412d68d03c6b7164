// One face of a light's distance cube map (u_face ≥ 0: rays from the light's position) or its distance plane
// (u_face < 0: parallel rays from the plane across the room): the distance to the first occluder — a sphere of the
// scene, a room box or an object an effect stands in the room — along each texel's ray, 1e30 where none.
#define MAX_OCCLUDERS 256
uniform int u_face;
uniform int u_size;
uniform vec3 u_light_origin;
uniform vec3 u_plane_origin;
uniform vec3 u_plane_u;
uniform vec3 u_plane_v;
uniform vec3 u_plane_direction;
uniform int u_occluder_count;
uniform vec4 u_occluders[MAX_OCCLUDERS];  // spheres: centre, radius
layout(location = 0) out vec4 out_distance;

float first_occluder(vec3 o, vec3 d) {
    float best = 1e30;
    for (int i = 0; i < u_occluder_count; ++i) {
        vec3 oc = o - u_occluders[i].xyz;
        float b = dot(oc, d);
        float h = b * b - (dot(oc, oc) - u_occluders[i].w * u_occluders[i].w);
        if (h < 0.0) continue;
        float t = -b - sqrt(h);
        if (t > 0.0 && t < best) best = t;
    }
    vec3 inv = vec3(1.0 / env_safe(d.x), 1.0 / env_safe(d.y), 1.0 / env_safe(d.z));
    for (int b = 0; b < u_box_count; ++b) {
        float t_near = -1e30, t_far = 1e30;
        for (int i = 0; i < 3; ++i) {
            float t1 = (u_box_min[b][i] - o[i]) * inv[i], t2 = (u_box_max[b][i] - o[i]) * inv[i];
            t_near = max(t_near, min(t1, t2));
            t_far = min(t_far, max(t1, t2));
        }
        if (t_near <= t_far && t_near > 0.0 && t_near < best) best = t_near;
    }
#if defined(ENVIRONMENT_OCCLUDER)
    best = min(best, ENVIRONMENT_OCCLUDER(o, d));  // what effects stand in the room (rings)
#endif
    return best;
}

void main() {
    vec3 o, d;
    if (u_face >= 0) {
        vec2 st = 2.0 * gl_FragCoord.xy / float(u_size) - 1.0;
        o = u_light_origin;
        d = normalize(cube_direction(u_face, st.x, st.y));
    } else {
        vec2 uv = gl_FragCoord.xy / float(u_size);
        o = u_plane_origin + uv.x * u_plane_u + uv.y * u_plane_v;
        d = u_plane_direction;
    }
    out_distance = vec4(first_occluder(o, d), 0.0, 0.0, 1.0);
}
