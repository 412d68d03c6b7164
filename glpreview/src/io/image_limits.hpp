// Which files are read, and what an image header may claim before any pixel is allocated (kMaxInputImageSide,
// kMaxInputImagePixels of glpreview/io/image_io.hpp, and a pixel budget by file size), shared by the EXR reader, the
// PNG reader and the OpenImageIO module.
#pragma once

#include <sys/stat.h>

#include <cstdint>
#include <filesystem>
#include <string>

#include "glpreview/io/image_io.hpp"

namespace metalfit::glpreview {

// Empty when the dimensions are within the limits; else the one-line reason.
inline std::string dimensions_problem(long long width, long long height, int channels, int depth = 1) {
    if (width > 0 && height > 0 && width <= kMaxInputImageSide && height <= kMaxInputImageSide &&
        width * height <= kMaxInputImagePixels && depth <= 1 && channels >= 1 && channels <= 64)
        return {};
    return "image dimensions " + std::to_string(width) + " x " + std::to_string(height) + " x " +
           std::to_string(channels) + " channels are outside the limits (sides up to " +
           std::to_string(kMaxInputImageSide) + ", " + std::to_string(kMaxInputImagePixels) + " pixels, 64 channels)";
}

// What a file's size lets its header claim (docs/scene.md, "Limits and checks"): any image up to kFreeImagePixels,
// beyond that at most one pixel per kFileBytesPerPixel bytes of the file. A header is a few bytes that can declare
// any size, and readers allocate what it declares before they find the pixels missing (a 21-byte Radiance header cost
// 1.5 GB). Real environments hold 2-6 bytes a pixel (EXR half RGB with ZIP or PIZ, Radiance's run-length code). An
// image file of at most 16 MiB therefore costs at most 2^23 pixels: glpreview rendering a 4096 x 2048 environment
// peaks at about 508 MiB.
inline constexpr long long kFreeImagePixels = 1LL << 23;  // 4096 x 2048
inline constexpr long long kFileBytesPerPixel = 2;

inline long long pixel_budget(std::uintmax_t file_bytes) {
    const std::uintmax_t earned = file_bytes / kFileBytesPerPixel;
    const std::uintmax_t cap = static_cast<std::uintmax_t>(kMaxInputImagePixels);
    const long long budget = static_cast<long long>(earned < cap ? earned : cap);
    return budget > kFreeImagePixels ? budget : kFreeImagePixels;
}

// Empty when a header's width x height fits the budget of a file of `file_bytes`; else the one-line reason.
inline std::string budget_problem(long long width, long long height, std::uintmax_t file_bytes) {
    if (width * height <= pixel_budget(file_bytes)) return {};
    return "the header declares " + std::to_string(width) + " x " + std::to_string(height) +
           " pixels but the file holds " + std::to_string(file_bytes) + " bytes (beyond " +
           std::to_string(kFreeImagePixels) + " pixels an image needs " + std::to_string(kFileBytesPerPixel) +
           " bytes of file per pixel it declares)";
}

// The size of a regular file (0 when it cannot be read: the reader then reports why).
inline std::uintmax_t file_bytes(const std::filesystem::path& file) {
    struct stat st {};
    return ::stat(file.c_str(), &st) == 0 ? static_cast<std::uintmax_t>(st.st_size) : 0;
}

// Empty when `file` is a regular file; else why it is not read (a FIFO or /dev/zero would hang or never end).
inline std::string not_a_file_problem(const std::filesystem::path& file) {
    struct stat st {};
    if (::stat(file.c_str(), &st) != 0) return "cannot read the image: no such file";
    if (!S_ISREG(st.st_mode)) return "cannot read the image: not a regular file";
    return {};
}

}  // namespace metalfit::glpreview
