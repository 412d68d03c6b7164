// draw_text through the OpenImageIO module (oiio/render_text.cpp), loaded on first use.
#include "glpreview/io/image_text.hpp"

#include "libfit/base/errors.hpp"
#include "oiio_module.hpp"

namespace metalfit::glpreview {

void draw_text(Image& image, const std::vector<TextBox>& boxes) {
    if (boxes.empty()) return;
    if (const std::string problem = oiio_module().draw_text(image, boxes); !problem.empty())
        throw InputError(InputLocation(std::string("font ") + kLabelFont), problem);
}

}  // namespace metalfit::glpreview
