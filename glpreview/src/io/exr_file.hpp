// OpenEXR files through OpenEXR's C++ API (Imf): reading one as linear RGB (write_exr, read_image_metadata and
// read_exr_colour are declared in glpreview/io/image_io.hpp).
#pragma once

#include <filesystem>
#include <utility>

#include "glpreview/io/image.hpp"

namespace metalfit::glpreview {

// True when the file starts with OpenEXR's magic number (the bytes 76 2f 31 01).
bool has_exr_signature(const std::filesystem::path& file);

// The first part's data window as RGB: R, G and B when present, a single channel (Y) repeated, else the first
// channels in name order (the last repeated), as OpenImageIO orders them. The header's dimensions are checked before
// any pixel is read. Throws InputError naming the file.
Image read_exr(const std::filesystem::path& file);
// The data window's width and height, after the same header checks as read_exr (no pixels read).
std::pair<int, int> read_exr_size(const std::filesystem::path& file);

}  // namespace metalfit::glpreview
