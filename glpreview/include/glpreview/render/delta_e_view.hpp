// ΔE2000 per pixel between a render and its reference (docs/preview.md, "Error views"): each pixel's working-space
// RGB → CIE XYZ through OCIO (the space's matrix, read once from the converter) → CIE L*a*b* relative to a stated
// white → libfit's ciede2000. HDR pixels have no white of their own: the white is the working space's white (RGB
// (1, 1, 1)) scaled to Y_w = kDeltaEWhiteY = 1, the radiance a PNG at exposure 0 shows as display white, so ΔE is
// the difference a viewer of beauty.png and reference.png sees, on a white that does not move with the picture.
// The view is a sequential colour map (black at 0) on a linear scale chosen from the data, with a colour bar.
// No GL.
#pragma once

#include <string>
#include <vector>

#include "glpreview/io/image.hpp"
#include "libfit/color/color.hpp"
#include "libfit/color/color_difference.hpp"
#include "libfit/color/color_space.hpp"
#include "libfit/color/matrix3.hpp"

namespace metalfit::glpreview {

// The reference white's luminance: linear radiance 1 (display white at exposure 0).
inline constexpr double kDeltaEWhiteY = 1.0;
// The view's top is at least this (ΔE 1: about one just-noticeable difference, always on the scale) and at most
// kDeltaEHighestTop.
inline constexpr double kDeltaELowestTop = 1.0;
inline constexpr double kDeltaEHighestTop = 100.0;

// A working space for colour differences: its RGB → XYZ matrix (columns: the XYZ of its primaries at unit value)
// and the white L*a*b* is taken against.
struct DeltaEBasis {
    Matrix3 rgb_to_xyz = Matrix3::identity();
    XYZ white{1, 1, 1};
};
// The converter's target space through OCIO (its inverse, RGB → XYZ): white = XYZ of RGB (1, 1, 1) × kDeltaEWhiteY / Y.
DeltaEBasis delta_e_basis(const ColorSpaceConverter& converter);

Lab pixel_lab(const RGB& rgb, const DeltaEBasis& basis);

// ΔE2000 of every pixel of `model` against `reference` (top row first; 0 where either pixel is not finite).
std::vector<double> delta_e_2000(const Image& model, const Image& reference, const DeltaEBasis& basis);

// The linear scale of the view: 0 is black, `largest` and above the map's end colour.
struct DeltaEScale {
    double largest = 10.0;
};
// The top: the smallest of 1, 2, 5 × 10^k at or above the 99.5th percentile of the nonzero ΔE (at least
// kDeltaELowestTop, at most kDeltaEHighestTop).
DeltaEScale delta_e_scale_from(const std::vector<double>& delta_e);

// Sequential colour (linear RGB; the display transform is applied to the view and its bar alike): black at 0, then
// the key colours of matplotlib's inferno (purple, red, orange, pale yellow at the top), luminance rising throughout.
RGB delta_e_colour(double delta_e, const DeltaEScale& scale);
// A vertical bar in the rectangle: `largest` at the top row, 0 (black) at the bottom row.
void paint_delta_e_bar(Image& image, int x0, int y0, int w, int h, const DeltaEScale& scale);

// The view of a width × height image's ΔE, on the scale chosen from them (returned in `scale`), with its colour bar
// at the right edge (render/error_view's layout).
Image delta_e_view_image(const std::vector<double>& delta_e, int width, int height, DeltaEScale& scale);

// "0..5 linear": the scale as the label says it.
std::string delta_e_scale_label(const DeltaEScale& scale);

}  // namespace metalfit::glpreview
