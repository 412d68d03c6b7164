// A sphere's distance map, a sphere in it: one cube face per draw, each texel's ray from the map's centre against the
// sphere u_hit (analytic). Writes the distance (a of the radiance layer; its rgb is not read where a mirror is seen),
// the sphere's normal and signed index (the hits layer), and depth t/(t+1) − u_depth_bias as the room and the
// spheres' own programs do (the bias lets a rough sphere's index land where its program drew it).
uniform int u_face;  // 0..5: +X, −X, +Y, −Y, +Z, −Z
uniform int u_size;
uniform vec3 u_map_center;
uniform vec3 u_hit_center;
uniform float u_hit_radius;
uniform float u_hit_index;  // j + 1 for mirror sphere j, −(j + 1) for rough sphere j
uniform float u_depth_bias;
layout(location = 0) out vec4 out_texel;
layout(location = 1) out vec4 out_hit;

void main() {
    vec2 st = 2.0 * gl_FragCoord.xy / float(u_size) - 1.0;
    vec3 d = normalize(cube_direction(u_face, st.x, st.y));
    vec3 oc = u_map_center - u_hit_center;
    float b = dot(oc, d);
    float h = b * b - (dot(oc, oc) - u_hit_radius * u_hit_radius);
    if (h < 0.0) discard;
    float t = -b - sqrt(h);
    if (t <= 0.0) discard;
    vec3 N = (u_map_center + t * d - u_hit_center) / u_hit_radius;
    out_texel = vec4(0.0, 0.0, 0.0, t);
    out_hit = vec4(N, u_hit_index);
    gl_FragDepth = t / (t + 1.0) - u_depth_bias;
}
