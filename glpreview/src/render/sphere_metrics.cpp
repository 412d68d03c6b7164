#include "glpreview/render/sphere_metrics.hpp"

#include <algorithm>
#include <cmath>
#include <stdexcept>

#include "libfit/base/sample_statistics.hpp"

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

std::vector<SphereDeltaE> sphere_delta_e(const std::vector<double>& delta_e, const ReferenceRender& reference,
                                         std::size_t spheres) {
    if (delta_e.size() != reference.sphere_id.size())
        throw std::invalid_argument("sphere_delta_e: images of different sizes");
    std::vector<std::vector<double>> values(spheres);
    for (std::size_t p = 0; p < delta_e.size(); ++p)
        if (const int id = reference.sphere_id[p]; id >= 0) values[static_cast<std::size_t>(id)].push_back(delta_e[p]);
    std::vector<SphereDeltaE> out(spheres);
    for (std::size_t s = 0; s < spheres; ++s) {
        double sum = 0;
        for (double d : values[s]) sum += d;
        out[s].mean = values[s].empty() ? std::nan("") : sum / static_cast<double>(values[s].size());
        out[s].p95 = quantile(std::move(values[s]), 0.95);  // NaN when empty
    }
    return out;
}

std::vector<double> sphere_reference_noise(const Image& standard_error, const ReferenceRender& reference,
                                           std::size_t spheres) {
    if (standard_error.width != reference.image.width || standard_error.height != reference.image.height)
        throw std::invalid_argument("sphere_reference_noise: images of different sizes");
    std::vector<double> squared(spheres, 0.0), count(spheres, 0.0);
    for (std::size_t p = 0; p < reference.sphere_id.size(); ++p) {
        const int id = reference.sphere_id[p];
        if (id < 0) continue;
        const auto s = static_cast<std::size_t>(id);
        for (int c = 0; c < 3; ++c)
            squared[s] += double(standard_error.rgb[3 * p + c]) * double(standard_error.rgb[3 * p + c]);
        count[s] += 3;
    }
    std::vector<double> noise(spheres);
    for (std::size_t s = 0; s < spheres; ++s) noise[s] = count[s] > 0 ? std::sqrt(squared[s] / count[s]) : std::nan("");
    return noise;
}

std::vector<SphereLocalization> sphere_localization(const Image& diagnostics, const ReferenceRender& reference,
                                                    std::size_t spheres) {
    if (diagnostics.width != reference.image.width || diagnostics.height != reference.image.height)
        throw std::invalid_argument("sphere_localization: images of different sizes");
    std::vector<SphereLocalization> out(spheres);
    std::vector<std::size_t> pixels(spheres, 0);
    for (std::size_t p = 0; p < reference.sphere_id.size(); ++p) {
        const int id = reference.sphere_id[p];
        if (id < 0) continue;
        SphereLocalization& s = out[static_cast<std::size_t>(id)];
        s.mean_iterations += diagnostics.rgb[3 * p];
        s.mean_rho_error += diagnostics.rgb[3 * p + 1];
        s.max_rho_error = std::max(s.max_rho_error, double(diagnostics.rgb[3 * p + 1]));
        ++pixels[static_cast<std::size_t>(id)];
    }
    for (std::size_t s = 0; s < spheres; ++s) {
        const double n = static_cast<double>(pixels[s]);
        out[s].mean_iterations = n > 0 ? out[s].mean_iterations / n : std::nan("");
        out[s].mean_rho_error = n > 0 ? out[s].mean_rho_error / n : std::nan("");
        if (n == 0) out[s].max_rho_error = std::nan("");
    }
    return out;
}

Image absolute_difference(const Image& a, const Image& b, double scale) {
    if (a.width != b.width || a.height != b.height)
        throw std::invalid_argument("absolute_difference: images of different sizes");
    Image out(a.width, a.height);
    for (std::size_t i = 0; i < a.rgb.size(); ++i)
        out.rgb[i] = static_cast<float>(scale * std::abs(double(a.rgb[i]) - double(b.rgb[i])));
    return out;
}

}  // namespace metalfit::glpreview
