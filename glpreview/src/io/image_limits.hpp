// Which files are read, and what an image header may claim before any pixel is allocated (kMaxInputImageSide,
// kMaxInputImagePixels of glpreview/io/image_io.hpp), shared by the EXR reader, the PNG reader and the OpenImageIO module.
#pragma once

#include <sys/stat.h>

#include <filesystem>
#include <string>

#include "glpreview/io/image_io.hpp"

namespace metalfit::glpreview {

// Empty when the dimensions are within the limits; else the one-line reason.
inline std::string dimensions_problem(long long width, long long height, int channels, int depth = 1) {
    if (width > 0 && height > 0 && width <= kMaxInputImageSide && height <= kMaxInputImageSide &&
        width * height <= kMaxInputImagePixels && depth <= 1 && channels >= 1 && channels <= 64)
        return {};
    return "image dimensions " + std::to_string(width) + " x " + std::to_string(height) + " x " + std::to_string(channels) +
           " channels are outside the limits (sides up to " + std::to_string(kMaxInputImageSide) + ", " +
           std::to_string(kMaxInputImagePixels) + " pixels, 64 channels)";
}

// Empty when `file` is a regular file; else why it is not read (a FIFO or /dev/zero would hang or never end).
inline std::string not_a_file_problem(const std::filesystem::path& file) {
    struct stat st {};
    if (::stat(file.c_str(), &st) != 0) return "cannot read the image: no such file";
    if (!S_ISREG(st.st_mode)) return "cannot read the image: not a regular file";
    return {};
}

}  // namespace metalfit::glpreview
