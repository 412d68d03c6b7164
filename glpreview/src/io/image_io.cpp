#include "glpreview/io/image_io.hpp"

#include <OpenImageIO/imageio.h>

#include <algorithm>
#include <cmath>
#include <random>
#include <system_error>

#include "libfit/base/errors.hpp"

namespace metalfit::glpreview {
namespace {

// "out/beauty.exr" → "out/.beauty.partial-<n>.exr": the extension is kept so that OpenImageIO picks the format.
std::filesystem::path temporary_beside(const std::filesystem::path& file) {
    std::random_device random;
    return file.parent_path() /
           ("." + file.stem().string() + ".partial-" + std::to_string(random() % 1000000) + file.extension().string());
}

// Writes pixels of `format` through OpenImageIO into a temporary file, then renames it over `file`.
void write_pixels(const std::filesystem::path& file, const OIIO::ImageSpec& spec, OIIO::TypeDesc format, const void* pixels) {
    const std::filesystem::path temporary = temporary_beside(file);
    auto fail = [&](const std::string& why) {
        std::error_code ignored;
        std::filesystem::remove(temporary, ignored);
        throw InputError(InputLocation(file), "cannot write the image: " + why);
    };
    auto out = OIIO::ImageOutput::create(file.string());
    if (!out) fail(OIIO::geterror());
    if (!out->open(temporary.string(), spec)) fail(out->geterror());
    if (!out->write_image(format, pixels)) fail(out->geterror());
    if (!out->close()) fail(out->geterror());
    std::error_code error;
    std::filesystem::rename(temporary, file, error);
    if (error) fail(error.message());
}

}  // namespace

Image read_image(const std::filesystem::path& file) {
    auto in = OIIO::ImageInput::open(file.string());
    if (!in) throw InputError(InputLocation(file), "cannot read the image: " + OIIO::geterror());
    const OIIO::ImageSpec& spec = in->spec();
    const int channels = spec.nchannels;
    std::vector<float> pixels(static_cast<std::size_t>(spec.width) * spec.height * channels);
    if (!in->read_image(0, 0, 0, channels, OIIO::TypeDesc::FLOAT, pixels.data()))
        throw InputError(InputLocation(file), "cannot read the image: " + in->geterror());
    Image image(spec.width, spec.height);
    for (std::size_t i = 0; i < static_cast<std::size_t>(spec.width) * spec.height; ++i)
        for (int c = 0; c < 3; ++c) image.rgb[3 * i + c] = pixels[i * channels + std::min(c, channels - 1)];
    for (float v : image.rgb)
        if (!std::isfinite(v) || v < 0) throw InputError(InputLocation(file), "pixels must be finite and non-negative radiance");
    return image;
}

void write_exr(const std::filesystem::path& file, const Image& image) {
    OIIO::ImageSpec spec(image.width, image.height, 3, OIIO::TypeDesc::HALF);
    spec.channelnames = {"R", "G", "B"};
    spec.attribute("compression", "zip");
    write_pixels(file, spec, OIIO::TypeDesc::FLOAT, image.rgb.data());
}

void write_png(const std::filesystem::path& file, const Image& image, const DisplayTransform& display) {
    const std::vector<unsigned char> pixels = display.apply(image.rgb, image.width, image.height);
    OIIO::ImageSpec spec(image.width, image.height, 3, OIIO::TypeDesc::UINT8);
    write_pixels(file, spec, OIIO::TypeDesc::UINT8, pixels.data());
}

Png8 read_png8(const std::filesystem::path& file) {
    auto in = OIIO::ImageInput::open(file.string());
    if (!in) throw InputError(InputLocation(file), "cannot read the image: " + OIIO::geterror());
    const OIIO::ImageSpec& spec = in->spec();
    if (spec.nchannels != 3) throw InputError(InputLocation(file), "expected an RGB image");
    Png8 png{spec.width, spec.height, std::vector<unsigned char>(static_cast<std::size_t>(spec.width) * spec.height * 3)};
    if (!in->read_image(0, 0, 0, 3, OIIO::TypeDesc::UINT8, png.rgb.data()))
        throw InputError(InputLocation(file), "cannot read the image: " + in->geterror());
    return png;
}

}  // namespace metalfit::glpreview
