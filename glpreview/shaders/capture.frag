// Environment capture: one cube face per draw; each texel ray-casts the environment from the reference point o.
// rgb: radiance, a: distance from o (read by the distance impostor).
uniform int u_face;  // 0..5: +X, −X, +Y, −Y, +Z, −Z
uniform int u_size;
layout(location = 0) out vec4 out_texel;

// The direction of face coordinates (s, t) ∈ [−1, 1]², as OpenGL's cube-map face selection defines them.
vec3 cube_direction(int face, float s, float t) {
    if (face == 0) return vec3(1.0, -t, -s);
    if (face == 1) return vec3(-1.0, -t, s);
    if (face == 2) return vec3(s, 1.0, t);
    if (face == 3) return vec3(s, -1.0, -t);
    if (face == 4) return vec3(s, -t, 1.0);
    return vec3(-s, -t, -1.0);
}

void main() {
    vec2 st = 2.0 * gl_FragCoord.xy / float(u_size) - 1.0;
    vec3 d = normalize(cube_direction(u_face, st.x, st.y));
    vec4 hit = environment_trace(u_reference, d);
    out_texel = vec4(hit.rgb, hit.a);
}
