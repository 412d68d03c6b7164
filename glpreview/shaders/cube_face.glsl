// Cube-map faces: the capture and the prefilter render one face per draw.
// The direction of face coordinates (s, t) ∈ [−1, 1]², as OpenGL's cube-map face selection defines them.
vec3 cube_direction(int face, float s, float t) {
    if (face == 0) return vec3(1.0, -t, -s);
    if (face == 1) return vec3(-1.0, -t, s);
    if (face == 2) return vec3(s, 1.0, t);
    if (face == 3) return vec3(s, -1.0, -t);
    if (face == 4) return vec3(s, -t, 1.0);
    return vec3(-s, -t, -1.0);
}
