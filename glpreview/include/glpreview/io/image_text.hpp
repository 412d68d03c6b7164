// Text drawn into a linear image with OpenImageIO's ImageBufAlgo::render_text (FreeType; in the OpenImageIO module,
// loaded on first use: src/io/oiio_module.hpp) in DejaVu Sans, the font of Debian's fonts-dejavu-core
// (scripts/install-deps.sh), found by OpenImageIO's own font search ($OPENIMAGEIO_FONTS, $HOME/fonts,
// /usr/share/fonts, ... searched recursively): nothing is downloaded.
#pragma once

#include <string>
#include <vector>

#include "glpreview/io/image.hpp"

namespace metalfit::glpreview {

inline constexpr const char* kLabelFont = "DejaVuSans";

// A line of text in a box of the image: left-aligned, white with a dark shadow, in the largest font size up to
// `font_size` that fits the box's width (at least 6 px), and never drawn outside the box.
struct TextBox {
    int x = 0, y = 0, width = 0, height = 0;
    std::string text;  // ASCII: OpenImageIO 2.4 draws one glyph per byte
    int font_size = 12;
};

// Throws InputError naming the font when OpenImageIO cannot find or load it (the package is missing);
// std::runtime_error when the OpenImageIO module is missing. No boxes: nothing is loaded.
void draw_text(Image& image, const std::vector<TextBox>& boxes);

}  // namespace metalfit::glpreview
