// Light maps of the procedural room's six faces (what the caustics and the indirect light add to its surfaces): a 2D
// texture array, layer 2·axis + side (side 0: the min plane), u and v along the face's two other axes in x, y, z
// order over the room's extent (shaders/room_face.glsl, RoomFace below), RGBA32F, each texel the value at its centre.
// Two effects keep one each, on the frame's blackboard under their own names.
#pragma once

#include <vector>

#include "glpreview/gl/objects.hpp"
#include "glpreview/scene/scene.hpp"

namespace metalfit::glpreview {

struct RoomLightMaps {
    struct Descriptor {
        int size = 256;  // texels per edge of each face
    };
    static RoomLightMaps create(const Descriptor& descriptor);  // cleared to 0
    gl::Texture texture;
    int size = 0;
};

// A face's corner at (u, v) = (0, 0) and its two axes over their lengths, and its inward normal.
struct RoomFace {
    Vec3 origin, u, v, normal;
    double texel_area(int size) const { return length(u) * length(v) / (static_cast<double>(size) * size); }
};
RoomFace room_face(const Room& room, int face);

// The maps read back, face by face (rgb per texel, row 0 at v = 0): tests and figures.
std::vector<std::vector<float>> read_room_light_maps(const RoomLightMaps& maps);

}  // namespace metalfit::glpreview
