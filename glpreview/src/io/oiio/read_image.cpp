// The module's image reader: any format OpenImageIO reads (glpreview reads EXRs itself), as RGB.
#include <OpenImageIO/imageio.h>

#include <algorithm>
#include <exception>
#include <memory>
#include <vector>

#include "../image_limits.hpp"
#include "module_functions.hpp"

namespace metalfit::glpreview::oiio {

std::string read_rgb(const char* file, Image& image, bool header_only) {
    std::unique_ptr<OIIO::ImageInput> in;
    try {
        in = OIIO::ImageInput::open(file);
    } catch (const std::exception& e) {
        return std::string("cannot read the image: ") + e.what();
    }
    if (!in) return "cannot read the image: " + OIIO::geterror();
    const OIIO::ImageSpec& spec = in->spec();
    std::string problem = dimensions_problem(spec.width, spec.height, spec.nchannels, spec.depth);
    if (problem.empty()) problem = budget_problem(spec.width, spec.height, file_bytes(file));
    if (!problem.empty()) return problem;
    if (header_only) {
        image.width = spec.width;
        image.height = spec.height;
        return {};
    }
    // At most three channels are converted (grey is expanded below, alpha and the rest dropped), in bands of rows
    // of about 8 MiB, so that nothing but the image itself grows with the image.
    const int channels = std::min(spec.nchannels, 3);
    const std::size_t row = static_cast<std::size_t>(spec.width) * channels;
    image = Image(spec.width, spec.height);
    auto copy = [&](const std::vector<float>& band, int y0, int rows) {
        for (std::size_t i = 0; i < static_cast<std::size_t>(rows) * spec.width; ++i)
            for (int c = 0; c < 3; ++c)
                image.rgb[3 * (static_cast<std::size_t>(y0) * spec.width + i) + c] =
                    band[i * channels + std::min(c, channels - 1)];
    };
    if (spec.tile_width > 0) {  // tiled (TIFF): the whole image at once
        std::vector<float> pixels(row * spec.height);
        if (!in->read_image(0, 0, 0, channels, OIIO::TypeDesc::FLOAT, pixels.data()))
            return "cannot read the image: " + in->geterror();
        copy(pixels, 0, spec.height);
        return {};
    }
    const int band_rows = static_cast<int>(std::max<std::size_t>(1, (std::size_t{8} << 20) / (row * sizeof(float))));
    std::vector<float> band;
    for (int y = 0; y < spec.height; y += band_rows) {
        const int rows = std::min(band_rows, spec.height - y);
        band.resize(row * rows);
        if (!in->read_scanlines(0, 0, spec.y + y, spec.y + y + rows, 0, 0, channels, OIIO::TypeDesc::FLOAT,
                                band.data()))
            return "cannot read the image: " + in->geterror();
        copy(band, y, rows);
    }
    return {};
}

}  // namespace metalfit::glpreview::oiio
