// Image files through OpenImageIO: linear EXR (half float) and 8-bit PNG through the OCIO display transform;
// reading HDR/EXR environment images. Files are written to a temporary name beside the target and renamed.
#pragma once

#include <filesystem>
#include <memory>
#include <string>

#include "glpreview/render/image.hpp"
#include "libfit/color/color_space.hpp"

namespace metalfit::glpreview {

// Any OpenImageIO file; RGB (a grey image is expanded, alpha dropped). Throws InputError naming the file.
Image read_image(const std::filesystem::path& file);

// Throws InputError naming the file when it cannot be written; never leaves a partial file.
void write_exr(const std::filesystem::path& file, const Image& image);

// scene_linear → the config's default display and view (metalfit's config: sRGB, Un-tone-mapped).
class DisplayTransform {
public:
    // Throws ColorConfigError naming the config.
    static DisplayTransform create(const OcioConfigChoice& config);
    // 8-bit display-referred RGB, rows as in the image.
    std::vector<unsigned char> apply(const Image& image) const;
    const std::string& description() const { return description_; }  // "Linear Rec.709 (sRGB) → sRGB - Display / Un-tone-mapped"

    ~DisplayTransform();
    DisplayTransform(DisplayTransform&&) noexcept;
    DisplayTransform& operator=(DisplayTransform&&) noexcept;

private:
    struct Impl;
    explicit DisplayTransform(std::unique_ptr<Impl> impl, std::string description);
    std::unique_ptr<Impl> impl_;
    std::string description_;
};

void write_png(const std::filesystem::path& file, const Image& image, const DisplayTransform& display);

// 8-bit RGB of a PNG (for golden-image tests).
struct Png8 {
    int width = 0, height = 0;
    std::vector<unsigned char> rgb;
};
Png8 read_png8(const std::filesystem::path& file);

}  // namespace metalfit::glpreview
