// A linear RGB float image, top row first (as written to files).
#pragma once

#include <cstddef>
#include <vector>

#include "glpreview/scene/vec3.hpp"

namespace metalfit::glpreview {

struct Image {
    int width = 0, height = 0;
    std::vector<float> rgb;  // width * height * 3, row-major, top row first

    Image() = default;
    Image(int w, int h) : width(w), height(h), rgb(static_cast<std::size_t>(w) * h * 3, 0.0f) {}

    std::size_t index(int x, int y) const { return 3 * (static_cast<std::size_t>(y) * width + x); }
    Vec3 at(int x, int y) const {
        const std::size_t i = index(x, y);
        return {rgb[i], rgb[i + 1], rgb[i + 2]};
    }
    void set(int x, int y, Vec3 v) {
        const std::size_t i = index(x, y);
        rgb[i] = static_cast<float>(v.x);
        rgb[i + 1] = static_cast<float>(v.y);
        rgb[i + 2] = static_cast<float>(v.z);
    }
};

}  // namespace metalfit::glpreview
