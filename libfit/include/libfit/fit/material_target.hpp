// A material as a fit target: the exact spectral reflectance of a bare metal, or of the stack of a film and/or a coat
// over it (Material::layers), integrated into R_c(μ) by ReferenceCurve. Its η is the metal's measured one, for
// the closed forms that sample n, k (for a stack too: the closed forms of the metal under the layers, starts and
// comparisons of the fit, as before the target was an object).
#pragma once

#include <memory>
#include <string>

#include "libfit/color/color_space.hpp"
#include "libfit/color/colorimetry.hpp"
#include "libfit/fit/fit_target.hpp"
#include "libfit/io/material.hpp"
#include "libfit/reference/reference_curve.hpp"
#include "libfit/reference/sampled_reference.hpp"

namespace metalfit {

class MaterialTarget final : public FitTarget {
public:
    // Throws InputError naming the material's (or a layer's) file when its data do not cover 360–830 nm (and
    // `spectral` does not extrapolate).
    MaterialTarget(const Material& material, const Colorimetry& colorimetry, const ColorSpaceConverter& converter,
                   const SpectralOptions& spectral, const ErrorSettings& error);

    std::shared_ptr<const SampledReference> reference() const override { return reference_; }
    RGB operator()(double mu) const override { return curve_(mu); }
    std::function<std::complex<double>(double nm)> eta() const override;
    std::string id() const override { return material_.id; }
    std::string describe() const override;
    InputLocation location() const override { return InputLocation(material_.provenance.file); }

    const Material& material() const { return material_; }
    const ReferenceCurve& curve() const { return curve_; }
    // Whether the target is a stack (a film and/or a coat over the metal) rather than the bare metal.
    bool layered() const;

private:
    Material material_;
    SpectralOptions spectral_;
    ReferenceCurve curve_;
    std::shared_ptr<const SampledReference> reference_;
};

}  // namespace metalfit
