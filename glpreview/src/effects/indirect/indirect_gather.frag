// One room face's indirect light map (indirect effect): per texel, the virtual lights' light at its centre per unit
// albedo (indirect_gather), the face's point and inward normal from room_face.glsl.
uniform int u_face;
uniform int u_size;
layout(location = 0) out vec4 out_radiance;

void main() {
    vec3 n;
    vec3 p = room_face_point(u_face, gl_FragCoord.xy / float(u_size), u_indirect_room_min, u_indirect_room_max, n);
    out_radiance = vec4(indirect_gather(p, n), 1.0);
}
