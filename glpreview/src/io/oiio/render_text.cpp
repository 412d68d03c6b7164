// The module's text drawing: OpenImageIO's ImageBufAlgo::render_text (FreeType) in DejaVu Sans (image_text.hpp).
#include <OpenImageIO/imagebuf.h>
#include <OpenImageIO/imagebufalgo.h>

#include <algorithm>
#include <stdexcept>

#include "module_functions.hpp"

namespace metalfit::glpreview::oiio {
namespace {

constexpr int kSmallestFont = 6;

struct FontMissing : std::runtime_error {
    using std::runtime_error::runtime_error;
};

// The width in pixels `text` takes at `size`; throws FontMissing when the font cannot be loaded.
int text_width(const std::string& text, int size) {
    const OIIO::ROI extent = OIIO::ImageBufAlgo::text_size(text, size, kLabelFont);
    if (!extent.defined())
        throw FontMissing(
            "OpenImageIO's font search did not find it (Debian package fonts-dejavu-core; or --sheet-labels off)");
    return extent.width();
}

}  // namespace

std::string draw_text(Image& image, const std::vector<TextBox>& boxes) try {
    const float white[3] = {1.0f, 1.0f, 1.0f};
    for (const TextBox& box : boxes) {
        const int x0 = std::max(box.x, 0), y0 = std::max(box.y, 0);
        const int x1 = std::min(box.x + box.width, image.width), y1 = std::min(box.y + box.height, image.height);
        if (box.text.empty() || x1 <= x0 || y1 <= y0) continue;
        int size = std::max(box.font_size, kSmallestFont);
        while (size > kSmallestFont && text_width(box.text, size) > box.width - 2) --size;
        (void)text_width(box.text, size);  // the font check, also when the first size fits
        // The box's pixels in a buffer of their own: glyphs and shadow cannot reach past the box.
        const int w = x1 - x0, h = y1 - y0;
        OIIO::ImageBuf patch(OIIO::ImageSpec(w, h, 3, OIIO::TypeDesc::FLOAT));
        for (int y = 0; y < h; ++y)
            for (int x = 0; x < w; ++x) {
                const RGB v = image.at(x0 + x, y0 + y);
                const float rgb[3] = {float(v.r), float(v.g), float(v.b)};
                patch.setpixel(x, y, rgb, 3);
            }
        // Baseline near the box's bottom, leaving room for descenders (about a fifth of the size).
        const int baseline = box.y + box.height - std::max(1, (box.height - size) / 2) - size / 5 - y0;
        if (!OIIO::ImageBufAlgo::render_text(patch, box.x + 1 - x0, baseline, box.text, size, kLabelFont, white,
                                             OIIO::ImageBufAlgo::TextAlignX::Left,
                                             OIIO::ImageBufAlgo::TextAlignY::Baseline, 1))
            return patch.geterror();
        for (int y = 0; y < h; ++y)
            for (int x = 0; x < w; ++x) {
                float rgb[3];
                patch.getpixel(x, y, rgb, 3);
                image.set(x0 + x, y0 + y, {rgb[0], rgb[1], rgb[2]});
            }
    }
    return {};
} catch (const FontMissing& e) {
    return e.what();
}

}  // namespace metalfit::glpreview::oiio
