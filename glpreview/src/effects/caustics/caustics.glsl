// The light the rings threw onto the room (caustics effect; docs/preview.md, "Caustics"): ENVIRONMENT_CAUSTICS adds a
// room surface's reflected radiance albedo / π × E, with E the caustic irradiance (W/m²) splatted into that face's
// light map. Only the room's own walls, floor and ceiling receive (a box's face is not on a room plane: none).
uniform sampler2DArray u_caustic_light;  // layer 2·axis + side (side 0: the min plane, 1: the max plane)
uniform vec3 u_caustic_room_min;
uniform vec3 u_caustic_room_max;

vec3 caustics_on_surface(vec3 albedo, vec3 p, vec3 n) {
    int face;
    vec2 uv;
    if (!room_face_of(p, n, u_caustic_room_min, u_caustic_room_max, face, uv)) return vec3(0.0);
    return albedo * texture(u_caustic_light, vec3(uv, float(face))).rgb / 3.14159265358979;
}
