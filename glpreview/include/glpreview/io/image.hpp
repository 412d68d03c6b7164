// A linear RGB float image, top row first (as written to files); pixels read and written as libfit RGB values.
#pragma once

#include <cstddef>
#include <vector>

#include "libfit/color/color.hpp"

namespace metalfit::glpreview {

struct Image {
    int width = 0, height = 0;
    std::vector<float> rgb;  // width * height * 3, row-major, top row first

    Image() = default;
    Image(int w, int h) : width(w), height(h), rgb(static_cast<std::size_t>(w) * h * 3, 0.0f) {}

    std::size_t index(int x, int y) const { return 3 * (static_cast<std::size_t>(y) * width + x); }
    RGB at(int x, int y) const {
        const std::size_t i = index(x, y);
        return {rgb[i], rgb[i + 1], rgb[i + 2]};
    }
    void set(int x, int y, RGB v) {
        const std::size_t i = index(x, y);
        rgb[i] = static_cast<float>(v.r);
        rgb[i + 1] = static_cast<float>(v.g);
        rgb[i + 2] = static_cast<float>(v.b);
    }
};

}  // namespace metalfit::glpreview
