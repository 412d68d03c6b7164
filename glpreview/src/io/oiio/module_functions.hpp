// The functions the module's table (module.cpp) points at, one file each.
#pragma once

#include <string>
#include <vector>

#include "../oiio_module.hpp"

namespace metalfit::glpreview::oiio {

std::string read_rgb(const char* file, Image& image, bool header_only);  // read_image.cpp
std::string draw_text(Image& image, const std::vector<TextBox>& boxes);  // render_text.cpp

}  // namespace metalfit::glpreview::oiio
