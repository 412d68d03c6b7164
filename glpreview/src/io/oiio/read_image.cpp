// The module's image reader: any format OpenImageIO reads (glpreview reads EXRs itself), as RGB.
#include <OpenImageIO/imageio.h>

#include <algorithm>
#include <exception>
#include <memory>

#include "../image_limits.hpp"
#include "module_functions.hpp"

namespace metalfit::glpreview::oiio {

std::string read_rgb(const char* file, Image& image) {
    std::unique_ptr<OIIO::ImageInput> in;
    try {
        in = OIIO::ImageInput::open(file);
    } catch (const std::exception& e) {
        return std::string("cannot read the image: ") + e.what();
    }
    if (!in) return "cannot read the image: " + OIIO::geterror();
    const OIIO::ImageSpec& spec = in->spec();
    const std::string problem = dimensions_problem(spec.width, spec.height, spec.nchannels, spec.depth);
    if (!problem.empty()) return problem;
    const int channels = spec.nchannels;
    const std::size_t count = static_cast<std::size_t>(spec.width) * spec.height;
    std::vector<float> pixels(count * channels);
    if (!in->read_image(0, 0, 0, channels, OIIO::TypeDesc::FLOAT, pixels.data())) return "cannot read the image: " + in->geterror();
    image = Image(spec.width, spec.height);
    for (std::size_t i = 0; i < count; ++i)
        for (int c = 0; c < 3; ++c) image.rgb[3 * i + c] = pixels[i * channels + std::min(c, channels - 1)];
    return {};
}

}  // namespace metalfit::glpreview::oiio
