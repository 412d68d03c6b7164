// The room's six faces as light maps are laid out (the caustics' and the indirect light's): face 2·axis + side (side
// 0: the min plane, whose inward normal points up the axis), u and v along the face's two other axes in x, y, z order,
// over the room's extent. room_face_of: the face a point with inward normal n lies on (false off the room's planes:
// a box's face); room_face_point: the point of a face at (u, v).
bool room_face_of(vec3 p, vec3 n, vec3 room_min, vec3 room_max, out int face, out vec2 uv) {
    int axis = abs(n.x) > 0.5 ? 0 : (abs(n.y) > 0.5 ? 1 : 2);
    int side = n[axis] > 0.0 ? 0 : 1;
    face = 2 * axis + side;
    float plane = side == 0 ? room_min[axis] : room_max[axis];
    int ua = axis == 0 ? 1 : 0, va = axis == 2 ? 1 : 2;
    uv = vec2((p[ua] - room_min[ua]) / (room_max[ua] - room_min[ua]), (p[va] - room_min[va]) / (room_max[va] - room_min[va]));
    return abs(p[axis] - plane) <= 1e-3;
}

vec3 room_face_point(int face, vec2 uv, vec3 room_min, vec3 room_max, out vec3 n) {
    int axis = face / 2, side = face - 2 * axis;
    int ua = axis == 0 ? 1 : 0, va = axis == 2 ? 1 : 2;
    vec3 p = room_min;
    p[axis] = side == 0 ? room_min[axis] : room_max[axis];
    p[ua] = room_min[ua] + uv.x * (room_max[ua] - room_min[ua]);
    p[va] = room_min[va] + uv.y * (room_max[va] - room_min[va]);
    n = vec3(0.0);
    n[axis] = side == 0 ? 1.0 : -1.0;
    return p;
}
