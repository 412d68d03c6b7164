// One face of the caustics' room distance cube: from the reference point o, the distance to the room's walls, floor,
// ceiling and boxes along each texel's ray (ROOM_ONLY: the rings are left out, so that a photon leaving a ring finds
// the room behind it), in alpha as the distance impostor reads it.
uniform int u_face;
uniform int u_size;
layout(location = 0) out vec4 out_texel;

void main() {
    vec2 st = 2.0 * gl_FragCoord.xy / float(u_size) - 1.0;
    vec3 d = normalize(cube_direction(u_face, st.x, st.y));
    out_texel = vec4(0.0, 0.0, 0.0, room_trace(u_reference, d).a);
}
