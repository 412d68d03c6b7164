#include "glpreview/render/rim_view.hpp"

#include <algorithm>
#include <cmath>
#include <numbers>

#include "glpreview/io/image_text.hpp"
#include "glpreview/render/rim_unwrap.hpp"
#include "glpreview/scene/camera.hpp"
#include "libfit/base/number_text.hpp"

namespace metalfit::glpreview {
namespace {

constexpr RGB kPlotBackground{0.01, 0.01, 0.01}, kPlotShade{0.06, 0.06, 0.06}, kPlotFrame{0.25, 0.25, 0.25};
constexpr RGB kChannel[3] = {{1.0, 0.08, 0.05}, {0.1, 0.9, 0.1}, {0.15, 0.3, 1.0}};

void fill(Image& image, int x0, int y0, int w, int h, RGB c) {
    for (int y = std::max(0, y0); y < std::min(image.height, y0 + h); ++y)
        for (int x = std::max(0, x0); x < std::min(image.width, x0 + w); ++x) image.set(x, y, c);
}

void blit(Image& image, int x0, int y0, const Image& strip, double scale = 1.0) {
    for (int y = 0; y < strip.height; ++y)
        for (int x = 0; x < strip.width; ++x) {
            const RGB c = strip.at(x, y);
            image.set(x0 + x, y0 + y, {c.r * scale, c.g * scale, c.b * scale});
        }
}

// F(μ) of both curves per channel over μ in [0, 1] (left to right), F in [0, 1] (bottom to top), the rim's μ
// range shaded.
void paint_fresnel_plot(Image& image, int x0, int y0, int w, int h, const SphereFresnel& shown,
                        const SphereFresnel& exact, const MuRange& rim) {
    fill(image, x0, y0, w, h, kPlotFrame);
    fill(image, x0 + 1, y0 + 1, w - 2, h - 2, kPlotBackground);
    const int px0 = x0 + 1, py0 = y0 + 1, pw = w - 2, ph = h - 2;
    const auto column = [&](double mu) { return px0 + static_cast<int>(std::lround(mu * (pw - 1))); };
    const auto row = [&](double f) {
        return py0 + static_cast<int>(std::lround((1.0 - std::clamp(f, 0.0, 1.0)) * (ph - 1)));
    };
    if (rim.pixels > 0) fill(image, column(rim.min), py0, column(rim.max) - column(rim.min) + 1, ph, kPlotShade);
    const bool one_curve = &shown == &exact || shown.fresnel == exact.fresnel;
    for (int pass = one_curve ? 1 : 0; pass < 2; ++pass) {
        const SphereFresnel& curve = pass == 0 ? exact : shown;  // the exact one first, dotted; the model over it
        std::array<int, 3> previous{};
        for (int x = 0; x < pw; ++x) {
            const RGB f = curve(static_cast<double>(x) / (pw - 1));
            const std::array<double, 3> value{f.r, f.g, f.b};
            for (int c = 0; c < 3; ++c) {
                const int y = row(value[c]);
                const int from = x == 0 ? y : previous[c];
                previous[c] = y;
                if (pass == 0 && !one_curve && (x / 2) % 2) continue;  // dotted
                for (int yy = std::min(from, y); yy <= std::max(from, y); ++yy) image.set(px0 + x, yy, kChannel[c]);
            }
        }
    }
}

}  // namespace

Image rim_view_image(const RimInputs& in) {
    const Scene& scene = in.scene;
    const int width = in.beauty.width, height = in.beauty.height;
    const CameraBasis camera = camera_basis(scene.camera, width, height);
    const std::vector<double> total = relative_luminance_error(in.beauty, in.reference.image, in.luminance);
    const std::vector<double> fit =
        in.fit_reference ? relative_luminance_error(in.beauty, *in.fit_reference, in.luminance) : std::vector<double>{};
    const int strips = in.fit_reference ? 4 : 3, strip_height = kRimLabelRows + kRimStripRows;
    const int row_height = strips * strip_height + 4;
    // One column per pixel of the longest rim, within the bounds.
    std::vector<RimGeometry> rims;
    double longest = 0;
    for (const Sphere& s : scene.spheres) {
        rims.emplace_back(camera, s, width, height);
        longest = std::max(longest, 2 * std::numbers::pi * rims.back().silhouette_distance(0.25 * std::numbers::pi));
    }
    const int columns = std::clamp(static_cast<int>(std::lround(longest)), kRimMinColumns, kRimMaxColumns);
    Image view(columns + kRimPlotWidth + 4, row_height * static_cast<int>(scene.spheres.size()));
    std::vector<TextBox> text;
    for (std::size_t i = 0; i < scene.spheres.size(); ++i) {
        const int top = static_cast<int>(i) * row_height;
        const RimUnwrap unwrap = unwrap_rim(rims[i], width, height, columns, kRimStripRows);
        const MuRange mu = rim_mu_range(rims[i], camera, scene.spheres[i], in.reference, static_cast<int>(i));
        const std::string name =
            "sphere " + std::to_string(i) + " " + in.shown[i]->material + ": " + in.shown[i]->fresnel;
        std::vector<std::pair<std::string, Image>> rows;
        rows.emplace_back(name + " - model (GPU), rim s = 1 (top) .. 0.9, phi 0..360 ccw from +x",
                          sample_rim(in.beauty, unwrap));
        rows.emplace_back("reference (CPU trace)", sample_rim(in.reference.image, unwrap));
        for (int k = 0; k < strips - 2; ++k) {
            const std::vector<double> errors = sample_rim(k == 0 ? total : fit, unwrap);
            const ErrorScale scale = error_scale_from(errors);
            Image strip(columns, kRimStripRows);
            paint_error_view(strip, 0, 0, columns, kRimStripRows, errors, scale);
            rows.emplace_back((k == 0 ? "model / traced reference - 1, " : "fit error: model / exact curve - 1, ") +
                                  scale_label(scale),
                              std::move(strip));
        }
        for (std::size_t k = 0; k < rows.size(); ++k) {
            const int y = top + static_cast<int>(k) * strip_height;
            blit(view, 0, y + kRimLabelRows, rows[k].second, k < 2 ? in.exposure : 1.0);
            text.push_back({0, y, columns, kRimLabelRows, rows[k].first, kRimLabelRows - 2});
        }
        const int plot_x = columns + 4, plot_h = strips * strip_height - 2 * kRimLabelRows;
        paint_fresnel_plot(view, plot_x, top + kRimLabelRows, kRimPlotWidth, plot_h, *in.shown[i], *in.exact[i], mu);
        text.push_back({plot_x, top, kRimPlotWidth, kRimLabelRows, "F(mu) 0..1: model solid, exact dotted; R G B",
                        kRimLabelRows - 2});
        const std::string range = mu.pixels > 0
                                      ? "rim pixels' mu " + fixed_text(mu.min, 2) + ".." + fixed_text(mu.max, 2) +
                                            " (" + std::to_string(mu.pixels) + " px, shaded)"
                                      : "no rim pixels";
        text.push_back({plot_x, top + kRimLabelRows + plot_h, kRimPlotWidth, kRimLabelRows, "mu 0..1; " + range,
                        kRimLabelRows - 2});
    }
    if (in.labels) draw_text(view, text);
    return view;
}

}  // namespace metalfit::glpreview
