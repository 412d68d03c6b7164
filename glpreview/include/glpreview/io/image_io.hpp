// Image files through OpenImageIO: linear EXR (half float) and 8-bit PNG through libfit's OCIO display transform;
// reading HDR/EXR environment images. Files are written to a temporary name beside the target and renamed.
#pragma once

#include <filesystem>
#include <string>

#include "glpreview/io/image.hpp"
#include "libfit/color/display_transform.hpp"

namespace metalfit::glpreview {

// Any OpenImageIO file; RGB (a grey image is expanded, alpha dropped). Throws InputError naming the file.
Image read_image(const std::filesystem::path& file);

// Throws InputError naming the file when it cannot be written; never leaves a partial file.
void write_exr(const std::filesystem::path& file, const Image& image);

void write_png(const std::filesystem::path& file, const Image& image, const DisplayTransform& display);

// 8-bit RGB of a PNG (for golden-image tests).
struct Png8 {
    int width = 0, height = 0;
    std::vector<unsigned char> rgb;
};
Png8 read_png8(const std::filesystem::path& file);

}  // namespace metalfit::glpreview
