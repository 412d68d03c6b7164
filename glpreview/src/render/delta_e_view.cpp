#include "glpreview/render/delta_e_view.hpp"

#include <algorithm>
#include <array>
#include <cmath>

#include "glpreview/render/error_view.hpp"
#include "libfit/base/number_text.hpp"
#include "libfit/base/sample_statistics.hpp"

namespace metalfit::glpreview {
namespace {

// matplotlib's inferno at 0, 1/4, 1/2, 3/4 and 1 (sRGB 8-bit (0, 0, 4), (87, 16, 110), (188, 55, 84),
// (249, 142, 9), (252, 255, 164)), decoded to linear RGB; the display transform encodes them back.
constexpr std::array<RGB, 5> kStops{{{0.0, 0.0, 0.0},
                                     {0.0953, 0.0052, 0.1559},
                                     {0.5029, 0.0382, 0.0887},
                                     {0.9473, 0.2705, 0.0027},
                                     {0.9734, 1.0, 0.3712}}};

}  // namespace

DeltaEBasis delta_e_basis(const ColorSpaceConverter& converter) {
    const XYZ r = converter.to_xyz(RGB{1, 0, 0}), g = converter.to_xyz(RGB{0, 1, 0}),
              b = converter.to_xyz(RGB{0, 0, 1});
    DeltaEBasis basis;
    basis.rgb_to_xyz = Matrix3{{{{r.X, g.X, b.X}, {r.Y, g.Y, b.Y}, {r.Z, g.Z, b.Z}}}};
    const XYZ white = basis.rgb_to_xyz * XYZ{1, 1, 1};
    const double scale = kDeltaEWhiteY / white.Y;
    basis.white = {white.X * scale, white.Y * scale, white.Z * scale};
    return basis;
}

Lab pixel_lab(const RGB& rgb, const DeltaEBasis& basis) {
    return xyz_to_lab(basis.rgb_to_xyz * XYZ{rgb.r, rgb.g, rgb.b}, basis.white);
}

std::vector<double> delta_e_2000(const Image& model, const Image& reference, const DeltaEBasis& basis) {
    std::vector<double> out(static_cast<std::size_t>(reference.width) * reference.height, 0.0);
    for (int y = 0; y < reference.height; ++y)
        for (int x = 0; x < reference.width; ++x) {
            const RGB m = model.at(x, y), r = reference.at(x, y);
            if (!std::isfinite(m.r + m.g + m.b) || !std::isfinite(r.r + r.g + r.b)) continue;
            out[static_cast<std::size_t>(y) * reference.width + x] =
                ciede2000(pixel_lab(r, basis), pixel_lab(m, basis));
        }
    return out;
}

DeltaEScale delta_e_scale_from(const std::vector<double>& delta_e) {
    std::vector<double> nonzero;
    for (double d : delta_e)
        if (d > 0) nonzero.push_back(d);
    const double high = nonzero.empty() ? 0.0 : quantile(std::move(nonzero), 0.995);
    // 1, 2, 5 × 10^k from the lowest top up, as integers and decades so that the label prints "5", never "5.0000001".
    for (int decade = 0;; ++decade)
        for (int step : {1, 2, 5}) {
            const double top = step * std::pow(10.0, decade);
            if (top >= kDeltaEHighestTop || (top >= kDeltaELowestTop && top >= high))
                return {std::min(top, kDeltaEHighestTop)};
        }
}

RGB delta_e_colour(double delta_e, const DeltaEScale& scale) {
    if (!(delta_e > 0)) return kStops[0];
    const double t = std::min(1.0, delta_e / scale.largest) * (kStops.size() - 1);
    const std::size_t i = std::min<std::size_t>(static_cast<std::size_t>(t), kStops.size() - 2);
    const double f = t - static_cast<double>(i);
    const RGB& a = kStops[i];
    const RGB& b = kStops[i + 1];
    return {a.r + (b.r - a.r) * f, a.g + (b.g - a.g) * f, a.b + (b.b - a.b) * f};
}

void paint_delta_e_bar(Image& image, int x0, int y0, int w, int h, const DeltaEScale& scale) {
    for (int y = 0; y < h; ++y) {
        const double value = h > 1 ? scale.largest * (1.0 - static_cast<double>(y) / (h - 1)) : 0.0;
        for (int x = 0; x < w; ++x) image.set(x0 + x, y0 + y, delta_e_colour(value, scale));
    }
}

Image delta_e_view_image(const std::vector<double>& delta_e, int width, int height, DeltaEScale& scale) {
    scale = delta_e_scale_from(delta_e);
    Image view(width, height);
    paint_view(view, 0, 0, width, height, delta_e, [&scale](double d) { return delta_e_colour(d, scale); });
    paint_colour_bar_at_right_edge(
        view, [&scale](Image& image, int x0, int y0, int w, int h) { paint_delta_e_bar(image, x0, y0, w, h, scale); });
    return view;
}

std::string delta_e_scale_label(const DeltaEScale& scale) { return "0.." + shortest_text(scale.largest) + " linear"; }

}  // namespace metalfit::glpreview
