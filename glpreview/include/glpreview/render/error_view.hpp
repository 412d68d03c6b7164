// The signed false-colour view of a fit's error (docs/preview.md, "Error views"): per pixel the relative luminance
// error e = Y_model / Y_reference − 1, on a logarithmic scale chosen from the data, in a diverging map with black at
// zero (the sheet's background, where model and reference agree exactly): warm where the model is brighter, cold
// where it is darker. No GL: the sheet's PNG and the tests use it on images already rendered.
#pragma once

#include <functional>
#include <string>
#include <vector>

#include "glpreview/io/image.hpp"
#include "libfit/color/color.hpp"
#include "libfit/color/color_space.hpp"

namespace metalfit::glpreview {

// The magnitudes the colours span: |e| ≤ smallest is black, |e| ≥ largest is the map's end colour, logarithmic in
// between.
struct ErrorScale {
    double smallest = 1e-5, largest = 1e-1;
};

// Below this the reference is dark enough that a relative error means nothing: such pixels show 0 (black).
inline constexpr double kErrorViewDarkReference = 1e-6;
// The decades the scale spans below its top, and the floors of both ends (float32 renders carry ~1e-7).
inline constexpr int kErrorViewDecades = 4;
inline constexpr double kErrorViewFloor = 1e-5;
inline constexpr double kErrorViewLowestTop = 1e-3;  // a 0.1 % error is always inside the scale, above its bottom

// Luminance weights of a linear RGB space: Y of its three primaries at unit value (the space's RGB → XYZ row).
using LuminanceWeights = RGB;
// Those of the converter's target space, through OCIO (its inverse, RGB → XYZ).
LuminanceWeights luminance_weights(const ColorSpaceConverter& converter);

// The signed relative luminance error of every pixel (0 where the reference is darker than
// kErrorViewDarkReference or either value is not finite).
std::vector<double> relative_luminance_error(const Image& model, const Image& reference, const LuminanceWeights& y);

// The scale from the errors of every cell it is drawn for: its top is the decade at or above the 99.5th percentile
// of |e| (at least kErrorViewLowestTop, at most 1), its bottom kErrorViewDecades below (at least kErrorViewFloor).
ErrorScale error_scale_from(const std::vector<double>& errors);

// The colour of a signed error: t = log10(|e| / smallest) / log10(largest / smallest), clamped to [0, 1]; black at
// t = 0, through red to yellow for e > 0, through blue to cyan for e < 0. Linear RGB (the PNG's display transform
// is applied to the view and its colour bar alike).
RGB error_colour(double e, const ErrorScale& scale);

// `values` (one per pixel of a w × h cell) as `colour` paints them, written into `image` at (x0, y0): the painting
// of every false-colour view (this signed one, the ΔE2000 view of render/delta_e_view).
void paint_view(Image& image, int x0, int y0, int w, int h, const std::vector<double>& values,
                const std::function<RGB(double)>& colour);

// `errors` (one per pixel of a w × h cell) as colours, written into `image` at (x0, y0).
void paint_error_view(Image& image, int x0, int y0, int w, int h, const std::vector<double>& errors,
                      const ErrorScale& scale);

// A vertical colour bar in the rectangle: +largest at the top, 0 (black) in the middle, −largest at the bottom.
void paint_colour_bar(Image& image, int x0, int y0, int w, int h, const ErrorScale& scale);

// A colour bar at the right edge of a whole image's view, between bands of a tenth of its height: `paint` is called
// with the bar's rectangle (x0, y0, w, h); nothing when the image is too small to hold it.
void paint_colour_bar_at_right_edge(Image& view, const std::function<void(Image&, int, int, int, int)>& paint);

// The label of a whole image's view, in a band at its top (white text, render_text: needs the OpenImageIO module).
void draw_view_label(Image& view, const std::string& text);

// A whole image's error view (a scene's fit-error.png and error.png): the errors of `model` against `reference` on
// the scale chosen from them, with a colour bar at the right edge; `scale` receives the scale.
Image error_view_image(const Image& model, const Image& reference, const LuminanceWeights& y, ErrorScale& scale);

// "±1e-05..0.1 log": the scale as the label under the view says it.
std::string scale_label(const ErrorScale& scale);

}  // namespace metalfit::glpreview
