#include "glpreview/render/room_light_maps.hpp"

#include "glpreview/gl/gl_context.hpp"

namespace metalfit::glpreview {

RoomLightMaps RoomLightMaps::create(const Descriptor& d) {
    RoomLightMaps maps{gl::create_texture(GL_TEXTURE_2D_ARRAY), d.size};
    glTextureStorage3D(maps.texture.id(), 1, GL_RGBA32F, d.size, d.size, 6);
    glTextureParameteri(maps.texture.id(), GL_TEXTURE_MIN_FILTER, GL_LINEAR);
    glTextureParameteri(maps.texture.id(), GL_TEXTURE_MAG_FILTER, GL_LINEAR);
    glTextureParameteri(maps.texture.id(), GL_TEXTURE_WRAP_S, GL_CLAMP_TO_EDGE);
    glTextureParameteri(maps.texture.id(), GL_TEXTURE_WRAP_T, GL_CLAMP_TO_EDGE);
    const float zero[4] = {0, 0, 0, 0};
    glClearTexImage(maps.texture.id(), 0, GL_RGBA, GL_FLOAT, zero);
    check_gl("creating the room's light maps");
    return maps;
}

RoomFace room_face(const Room& room, int face) {
    const int axis = face / 2, side = face % 2;
    const int ua = axis == 0 ? 1 : 0, va = axis == 2 ? 1 : 2;
    RoomFace f{room.min, {0, 0, 0}, {0, 0, 0}, {0, 0, 0}};
    f.origin[axis] = side == 0 ? room.min[axis] : room.max[axis];
    f.u[ua] = room.max[ua] - room.min[ua];
    f.v[va] = room.max[va] - room.min[va];
    f.normal[axis] = side == 0 ? 1 : -1;
    return f;
}

std::vector<std::vector<float>> read_room_light_maps(const RoomLightMaps& maps) {
    std::vector<float> all(static_cast<std::size_t>(maps.size) * maps.size * 6 * 4);
    glGetTextureImage(maps.texture.id(), 0, GL_RGBA, GL_FLOAT, static_cast<GLsizei>(all.size() * sizeof(float)),
                      all.data());
    std::vector<std::vector<float>> layers(6);
    const std::size_t texels = static_cast<std::size_t>(maps.size) * maps.size;
    for (std::size_t layer = 0; layer < 6; ++layer)
        for (std::size_t t = 0; t < texels; ++t)
            for (std::size_t c = 0; c < 3; ++c) layers[layer].push_back(all[(layer * texels + t) * 4 + c]);
    return layers;
}

}  // namespace metalfit::glpreview
