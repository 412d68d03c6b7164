// Image files: linear EXR (half float, through OpenEXR) and 8-bit PNG through libfit's OCIO display transform (through
// libpng); environment images read as EXR, or in any other format through the OpenImageIO module loaded on first use
// (src/io/oiio_module.hpp). Files are written to a temporary name beside the target and renamed.
#pragma once

#include <filesystem>
#include <optional>
#include <string>
#include <utility>
#include <variant>
#include <vector>

#include "glpreview/io/image.hpp"
#include "libfit/color/chromaticities.hpp"
#include "libfit/color/display_transform.hpp"

namespace metalfit::glpreview {

// The largest image read (an environment map): sides up to 16384 and 2^27 pixels (16384 x 8192, 1.5 GiB as float
// RGB); a header claiming more is refused before any pixel is read.
inline constexpr int kMaxInputImageSide = 16384;
inline constexpr long long kMaxInputImagePixels = 1LL << 27;

// An EXR (recognised by its magic number) or any file OpenImageIO reads (a regular file: FIFOs and devices are
// refused); RGB (a grey image is expanded, alpha dropped). Throws InputError naming the file; std::runtime_error when
// a non-EXR file needs the OpenImageIO module and it is missing.
Image read_image(const std::filesystem::path& file);
// The width and height read_image would return, from the header alone, with the same checks (its fuzz target).
std::pair<int, int> read_image_size(const std::filesystem::path& file);

// What an EXR says about its pixels besides them (docs/preview.md, "Outputs"): the working space's primaries and
// white (the standard `chromaticities` attribute) and its OCIO name (`colorSpace`, a string attribute).
struct ExrColour {
    Chromaticities chromaticities;
    std::string space;
};

// A named header attribute of an EXR (docs/preview.md, "Outputs"): a string, a float or an int.
struct ExrAttribute {
    std::string name;  // "metalfit/sphere0/material"
    std::variant<std::string, float, int> value;
};
using ExrMetadata = std::vector<ExrAttribute>;

// Throws InputError naming the file when it cannot be written; never leaves a partial file. Without `colour` the
// file carries no chromaticities (readers then assume Rec.709); `metadata` goes into the header as it is.
void write_exr(const std::filesystem::path& file, const Image& image, const ExrColour* colour = nullptr,
               const ExrMetadata& metadata = {});
// One float channel named `channel` (width × height values, top row first; a measure, not a colour: no
// chromaticities), with the same header attributes otherwise. Staged as write_exr.
void write_exr_channel(const std::filesystem::path& file, int width, int height, const std::vector<float>& values,
                       const std::string& channel, const ExrMetadata& metadata = {});
// Every string, float and int header attribute of an EXR whose name starts with `prefix`.
ExrMetadata read_image_metadata(const std::filesystem::path& file, const std::string& prefix);
// The chromaticities and colour space an EXR says it holds (nothing when it carries no `chromaticities`).
std::optional<ExrColour> read_exr_colour(const std::filesystem::path& file);

void write_png(const std::filesystem::path& file, const Image& image, const DisplayTransform& display);

// 8-bit RGB of a PNG (for golden-image tests).
struct Png8 {
    int width = 0, height = 0;
    std::vector<unsigned char> rgb;
};
Png8 read_png8(const std::filesystem::path& file);

}  // namespace metalfit::glpreview
