// Cube-map faces: the capture and the prefilter render one face per draw; the downsample and the localized sum
// take the solid angles of face rectangles.
// The direction of face coordinates (s, t) ∈ [−1, 1]², as OpenGL's cube-map face selection defines them.
vec3 cube_direction(int face, float s, float t) {
    if (face == 0) return vec3(1.0, -t, -s);
    if (face == 1) return vec3(-1.0, -t, s);
    if (face == 2) return vec3(s, 1.0, t);
    if (face == 3) return vec3(s, -1.0, -t);
    if (face == 4) return vec3(s, -t, 1.0);
    return vec3(-s, -t, -1.0);
}

// Solid angle from the cube's centre of the face rectangle [s0, s1] × [t0, t1] (cube of edge 2): the signed corner
// terms atan(s t / √(s² + t² + 1)).
float face_corner_area(float s, float t) { return atan(s * t, sqrt(s * s + t * t + 1.0)); }
float face_rectangle_solid_angle(float s0, float s1, float t0, float t1) {
    return face_corner_area(s1, t1) - face_corner_area(s0, t1) - face_corner_area(s1, t0) + face_corner_area(s0, t0);
}
