#include "glpreview/render/error_view.hpp"

#include <algorithm>
#include <cmath>

#include "glpreview/io/image_text.hpp"
#include "libfit/base/number_text.hpp"
#include "libfit/base/sample_statistics.hpp"

namespace metalfit::glpreview {
namespace {

double luminance(const RGB& c, const LuminanceWeights& y) { return y.r * c.r + y.g * c.g + y.b * c.b; }

RGB mix(const RGB& a, const RGB& b, double t) {
    return {a.r + (b.r - a.r) * t, a.g + (b.g - a.g) * t, a.b + (b.b - a.b) * t};
}

// The two arms of the map (linear RGB): black, a saturated middle, a light end; lightness grows with t on both.
constexpr RGB kBlack{0.0, 0.0, 0.0};
constexpr RGB kWarmMiddle{0.55, 0.04, 0.01}, kWarmEnd{1.0, 0.85, 0.25};
constexpr RGB kColdMiddle{0.02, 0.08, 0.60}, kColdEnd{0.30, 0.90, 1.0};

}  // namespace

LuminanceWeights luminance_weights(const ColorSpaceConverter& converter) {
    return {converter.to_xyz(RGB{1, 0, 0}).Y, converter.to_xyz(RGB{0, 1, 0}).Y, converter.to_xyz(RGB{0, 0, 1}).Y};
}

std::vector<double> relative_luminance_error(const Image& model, const Image& reference, const LuminanceWeights& y) {
    std::vector<double> errors(static_cast<std::size_t>(reference.width) * reference.height, 0.0);
    for (int py = 0; py < reference.height; ++py)
        for (int px = 0; px < reference.width; ++px) {
            const double ref = luminance(reference.at(px, py), y), mod = luminance(model.at(px, py), y);
            if (std::isfinite(ref) && std::isfinite(mod) && ref > kErrorViewDarkReference)
                errors[static_cast<std::size_t>(py) * reference.width + px] = mod / ref - 1.0;
        }
    return errors;
}

ErrorScale error_scale_from(const std::vector<double>& errors) {
    std::vector<double> magnitudes;
    magnitudes.reserve(errors.size());
    for (double e : errors)
        if (e != 0.0) magnitudes.push_back(std::abs(e));
    const double high = magnitudes.empty() ? 0.0 : quantile(std::move(magnitudes), 0.995);
    // Decade exponents as integers, so that the labels read "1e-05", never "1.0000000000000001e-05".
    const int lowest_top = static_cast<int>(std::lround(std::log10(kErrorViewLowestTop)));
    const int top =
        std::clamp(high > 0 ? static_cast<int>(std::ceil(std::log10(high) - 1e-9)) : lowest_top, lowest_top, 0);
    const int floor = static_cast<int>(std::lround(std::log10(kErrorViewFloor)));
    const int bottom = std::max(top - kErrorViewDecades, floor);
    return {std::pow(10.0, bottom), std::pow(10.0, top)};
}

RGB error_colour(double e, const ErrorScale& scale) {
    if (!(std::abs(e) > scale.smallest)) return kBlack;
    const double t =
        std::min(1.0, std::log10(std::abs(e) / scale.smallest) / std::log10(scale.largest / scale.smallest));
    const RGB& middle = e > 0 ? kWarmMiddle : kColdMiddle;
    const RGB& end = e > 0 ? kWarmEnd : kColdEnd;
    return t < 0.5 ? mix(kBlack, middle, 2 * t) : mix(middle, end, 2 * t - 1);
}

void paint_view(Image& image, int x0, int y0, int w, int h, const std::vector<double>& values,
                const std::function<RGB(double)>& colour) {
    for (int y = 0; y < h; ++y)
        for (int x = 0; x < w; ++x) image.set(x0 + x, y0 + y, colour(values[static_cast<std::size_t>(y) * w + x]));
}

void paint_error_view(Image& image, int x0, int y0, int w, int h, const std::vector<double>& errors,
                      const ErrorScale& scale) {
    paint_view(image, x0, y0, w, h, errors, [&scale](double e) { return error_colour(e, scale); });
}

void paint_colour_bar(Image& image, int x0, int y0, int w, int h, const ErrorScale& scale) {
    const double decades = std::log10(scale.largest / scale.smallest);
    for (int y = 0; y < h; ++y) {
        // s from +1 (top row) to −1 (bottom row); |s| is t, the position on the log scale.
        const double s = h > 1 ? 1.0 - 2.0 * y / (h - 1) : 0.0;
        const double e = s == 0 ? 0.0 : std::copysign(scale.smallest * std::pow(10.0, std::abs(s) * decades), s);
        for (int x = 0; x < w; ++x) image.set(x0 + x, y0 + y, std::abs(s) < 1e-9 ? kBlack : error_colour(e, scale));
    }
}

Image error_view_image(const Image& model, const Image& reference, const LuminanceWeights& y, ErrorScale& scale) {
    const std::vector<double> errors = relative_luminance_error(model, reference, y);
    scale = error_scale_from(errors);
    Image view(reference.width, reference.height);
    paint_error_view(view, 0, 0, view.width, view.height, errors, scale);
    paint_colour_bar_at_right_edge(
        view, [&scale](Image& image, int x0, int y0, int w, int h) { paint_colour_bar(image, x0, y0, w, h, scale); });
    return view;
}

void paint_colour_bar_at_right_edge(Image& view, const std::function<void(Image&, int, int, int, int)>& paint) {
    const int width = std::max(3, view.width / 48), margin = std::max(1, view.width / 96);
    const int top = std::max(margin, view.height / 10);
    if (view.width > width + 2 * margin && view.height > 2 * top)
        paint(view, view.width - width - margin, top, width, view.height - 2 * top);
}

void draw_view_label(Image& view, const std::string& text) {
    const int band = std::clamp(view.height / 12, 8, 28);
    draw_text(view, {{0, 0, view.width, band, text, band - 2}});
}

std::string scale_label(const ErrorScale& scale) {
    return "+-" + shortest_text(scale.smallest) + ".." + shortest_text(scale.largest) + " log";
}

}  // namespace metalfit::glpreview
