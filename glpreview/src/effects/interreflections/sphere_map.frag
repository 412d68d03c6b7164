// A sphere's distance map, the room part: one cube face per draw; each texel ray-casts the environment from the
// sphere's centre. rgb: radiance, a: the distance from the centre; depth t/(t+1), as the spheres drawn after it
// write theirs, so that a room box in front of another sphere hides it.
uniform int u_face;  // 0..5: +X, −X, +Y, −Y, +Z, −Z
uniform int u_size;
uniform vec3 u_map_center;
layout(location = 0) out vec4 out_texel;

void main() {
    vec2 st = 2.0 * gl_FragCoord.xy / float(u_size) - 1.0;
    vec3 d = normalize(cube_direction(u_face, st.x, st.y));
    vec4 hit = environment_trace(u_map_center, d);
    out_texel = hit;
    gl_FragDepth = hit.a / (hit.a + 1.0);
}
