// The light the rings threw onto the room (caustics effect; docs/preview.md, "Caustics"): ENVIRONMENT_CAUSTICS adds a
// room surface's reflected radiance albedo / π × E, with E the caustic irradiance (W/m²) splatted into that face's
// light map. Only the room's own walls, floor and ceiling receive (a box's face is not on a room plane: none).
uniform sampler2DArray u_caustic_light;  // layer 2·axis + side (side 0: the min plane, 1: the max plane)
uniform vec3 u_caustic_room_min;
uniform vec3 u_caustic_room_max;

vec3 caustics_on_surface(vec3 albedo, vec3 p, vec3 n) {
    int axis = abs(n.x) > 0.5 ? 0 : (abs(n.y) > 0.5 ? 1 : 2);
    int side = n[axis] > 0.0 ? 0 : 1;  // the inward normal of the min plane points up the axis
    float plane = side == 0 ? u_caustic_room_min[axis] : u_caustic_room_max[axis];
    if (abs(p[axis] - plane) > 1e-3) return vec3(0.0);
    int ua = axis == 0 ? 1 : 0, va = axis == 2 ? 1 : 2;
    vec2 uv = vec2((p[ua] - u_caustic_room_min[ua]) / (u_caustic_room_max[ua] - u_caustic_room_min[ua]),
                   (p[va] - u_caustic_room_min[va]) / (u_caustic_room_max[va] - u_caustic_room_min[va]));
    vec3 irradiance = texture(u_caustic_light, vec3(uv, float(2 * axis + side))).rgb;
    return albedo * irradiance / 3.14159265358979;
}
