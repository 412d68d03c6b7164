// read_image: the checks every image read shares, then the reader of the file's format (OpenEXR for EXRs, the
// OpenImageIO module for the rest).
#include "glpreview/io/image_io.hpp"

#include <cmath>

#include "exr_file.hpp"
#include "image_limits.hpp"
#include "libfit/base/errors.hpp"
#include "oiio_module.hpp"

namespace metalfit::glpreview {

std::pair<int, int> read_image_size(const std::filesystem::path& file) {
    if (const std::string problem = not_a_file_problem(file); !problem.empty())
        throw InputError(InputLocation(file), problem);
    if (has_exr_signature(file)) return read_exr_size(file);
    Image header;
    if (const std::string problem = oiio_module().read_rgb(file.c_str(), header, true); !problem.empty())
        throw InputError(InputLocation(file), problem);
    return {header.width, header.height};
}

Image read_image(const std::filesystem::path& file) {
    if (const std::string problem = not_a_file_problem(file); !problem.empty())
        throw InputError(InputLocation(file), problem);
    Image image;
    if (has_exr_signature(file))
        image = read_exr(file);
    else if (const std::string problem = oiio_module().read_rgb(file.c_str(), image, false); !problem.empty())
        throw InputError(InputLocation(file), problem);
    for (float v : image.rgb)
        if (!std::isfinite(v) || v < 0)
            throw InputError(InputLocation(file), "pixels must be finite and non-negative radiance");
    return image;
}

}  // namespace metalfit::glpreview
