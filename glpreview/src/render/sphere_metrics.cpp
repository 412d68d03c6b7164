#include "glpreview/render/sphere_metrics.hpp"

#include <cmath>
#include <stdexcept>

namespace metalfit::glpreview {

std::vector<SphereError> sphere_errors(const Image& beauty, const ReferenceRender& reference, std::size_t spheres) {
    if (beauty.width != reference.image.width || beauty.height != reference.image.height)
        throw std::invalid_argument("sphere_errors: images of different sizes");
    std::vector<double> squared(spheres, 0.0), absolute(spheres, 0.0);
    std::vector<SphereError> errors(spheres);
    for (std::size_t p = 0; p < reference.sphere_id.size(); ++p) {
        const int id = reference.sphere_id[p];
        if (id < 0) continue;
        const auto s = static_cast<std::size_t>(id);
        for (int c = 0; c < 3; ++c) {
            const double d = double(beauty.rgb[3 * p + c]) - double(reference.image.rgb[3 * p + c]);
            squared[s] += d * d;
            absolute[s] += std::abs(d);
        }
        ++errors[s].pixels;
    }
    for (std::size_t s = 0; s < spheres; ++s) {
        const double n = 3.0 * static_cast<double>(errors[s].pixels);
        errors[s].rmse = n > 0 ? std::sqrt(squared[s] / n) : std::nan("");
        errors[s].mean_abs = n > 0 ? absolute[s] / n : std::nan("");
    }
    return errors;
}

Image absolute_difference(const Image& a, const Image& b, double scale) {
    if (a.width != b.width || a.height != b.height) throw std::invalid_argument("absolute_difference: images of different sizes");
    Image out(a.width, a.height);
    for (std::size_t i = 0; i < a.rgb.size(); ++i)
        out.rgb[i] = static_cast<float>(scale * std::abs(double(a.rgb[i]) - double(b.rgb[i])));
    return out;
}

}  // namespace metalfit::glpreview
