#include "glpreview/render/spectral_fresnel.hpp"

#include <algorithm>
#include <stdexcept>

#include "libfit/optics/fresnel_real.hpp"
#include "libfit/reference/stack_grid.hpp"

namespace metalfit::glpreview {

SpectralFresnel::SpectralFresnel(const Material& material, const Colorimetry& colorimetry, SpectralOptions options) {
    const DenseSpectrum<XYZ>& grid = colorimetry.weights();
    if (material.layers && !material.layers->empty()) {
        require_layer_coverage(*material.layers, kVisibleRange, options);
        stack_ = stack_optics_on_grid(material, grid.first_nm(), grid.last_nm(), options);
        return;
    }
    for (std::size_t i = 0; i < grid.size(); ++i) {
        const SquaredIndex<double> e =
            squared_index(material.index(grid.nm(i), options.interpolation, options.out_of_range));
        eta2_re_.push_back(e.re);
        eta2_re_minus_1_.push_back(e.re_minus_1);
        eta2_im_.push_back(e.im);
        eta2_norm2_.push_back(e.norm2);
    }
}

void SpectralFresnel::multiply(double mu, std::span<double> spectrum) const {
    if (spectrum.size() != size()) throw std::invalid_argument("SpectralFresnel::multiply: not on the grid");
    mu = std::clamp(mu, 0.0, 1.0);
    if (!stack_.empty()) {
        for (std::size_t i = 0; i < stack_.size(); ++i) spectrum[i] *= stack_reflectance_unpolarized(mu, stack_[i]);
        return;
    }
    for (std::size_t i = 0; i < eta2_re_.size(); ++i)
        spectrum[i] *= fresnel_real(mu, eta2_re_[i], eta2_re_minus_1_[i], eta2_im_[i], eta2_norm2_[i]);
}

}  // namespace metalfit::glpreview
