#include "glpreview/render/rgb_uplift.hpp"

#include <cmath>
#include <stdexcept>

#include "libfit/color/matrix3.hpp"

namespace metalfit::glpreview {
namespace {

constexpr double kBlueGreenNm = 490, kGreenRedNm = 585, kScaleNm = 15;

double sigmoid(double x) { return 1.0 / (1.0 + std::exp(-x / kScaleNm)); }

}  // namespace

RgbUplift::RgbUplift(const Colorimetry& colorimetry, ColorSpaceConverter converter) : converter_(std::move(converter)) {
    const DenseSpectrum<XYZ>& grid = colorimetry.weights();
    for (std::size_t i = 0; i < grid.size(); ++i) weights_.push_back(grid[i]);
    raw_white_ = converter_(colorimetry.white());
    // The windows g_j (red, green, blue), a partition of unity.
    std::array<std::vector<double>, 3> windows;
    for (std::size_t i = 0; i < grid.size(); ++i) {
        const double nm = grid.nm(i);
        const double to_green = sigmoid(nm - kBlueGreenNm), to_red = sigmoid(nm - kGreenRedNm);
        windows[0].push_back(to_red);
        windows[1].push_back(to_green - to_red);
        windows[2].push_back(1.0 - to_green);
    }
    Matrix3 p;  // column j: RGB of window j
    for (int j = 0; j < 3; ++j) {
        const RGB c = rgb_of(windows[static_cast<std::size_t>(j)]);
        for (int i = 0; i < 3; ++i) p.m[static_cast<std::size_t>(i)][static_cast<std::size_t>(j)] = c[i];
    }
    const Matrix3 p_inverse = inverse(p);
    for (int c = 0; c < 3; ++c) {
        std::vector<double>& b = basis_[static_cast<std::size_t>(c)];
        b.assign(grid.size(), 0.0);
        for (int j = 0; j < 3; ++j)
            for (std::size_t i = 0; i < grid.size(); ++i)
                b[i] += p_inverse(j, c) * windows[static_cast<std::size_t>(j)][i];
        for (std::size_t i = 0; i < grid.size(); ++i)
            lifted_[static_cast<std::size_t>(c)].push_back(b[i] * weights_[i]);
    }
}

std::vector<double> RgbUplift::spectrum(const RGB& radiance) const {
    std::vector<double> s(size(), 0.0);
    for (int c = 0; c < 3; ++c)
        for (std::size_t i = 0; i < s.size(); ++i) s[i] += radiance[c] * basis_[static_cast<std::size_t>(c)][i];
    return s;
}

RGB RgbUplift::rgb(std::span<const double> throughput, const RGB& radiance) const {
    if (throughput.size() != size()) throw std::invalid_argument("RgbUplift::rgb: throughput not on the grid");
    XYZ sum{0, 0, 0};
    for (int c = 0; c < 3; ++c) {
        const std::vector<XYZ>& lifted = lifted_[static_cast<std::size_t>(c)];
        XYZ channel{0, 0, 0};
        for (std::size_t i = 0; i < throughput.size(); ++i) channel += throughput[i] * lifted[i];
        sum += radiance[c] * channel;
    }
    return converter_(sum) / raw_white_;
}

RGB RgbUplift::rgb_of(std::span<const double> spectrum) const {
    if (spectrum.size() != size()) throw std::invalid_argument("RgbUplift::rgb_of: spectrum not on the grid");
    XYZ sum{0, 0, 0};
    for (std::size_t i = 0; i < spectrum.size(); ++i) sum += spectrum[i] * weights_[i];
    return converter_(sum) / raw_white_;
}

}  // namespace metalfit::glpreview
