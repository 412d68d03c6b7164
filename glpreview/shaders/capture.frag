// Environment capture: one cube face per draw; each texel ray-casts the environment from the reference point o.
// rgb: radiance, a: distance from o (read by the distance impostor).
uniform int u_face;  // 0..5: +X, −X, +Y, −Y, +Z, −Z
uniform int u_size;
layout(location = 0) out vec4 out_texel;

void main() {
    vec2 st = 2.0 * gl_FragCoord.xy / float(u_size) - 1.0;
    vec3 d = normalize(cube_direction(u_face, st.x, st.y));
    vec4 hit = environment_trace(u_reference, d);
    out_texel = vec4(hit.rgb, hit.a);
}
