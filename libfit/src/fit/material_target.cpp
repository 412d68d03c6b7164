#include "libfit/fit/material_target.hpp"

#include "libfit/io/layer_stack.hpp"

namespace metalfit {

MaterialTarget::MaterialTarget(const Material& material, const Colorimetry& colorimetry,
                               const ColorSpaceConverter& converter, const SpectralOptions& spectral,
                               const ErrorSettings& error)
    : material_(material),
      spectral_(spectral),
      curve_(material_, colorimetry, converter, spectral),
      reference_(std::make_shared<const SampledReference>(curve_, error)) {}

std::function<std::complex<double>(double nm)> MaterialTarget::eta() const {
    return [this](double nm) { return material_.index(nm, spectral_.interpolation, spectral_.out_of_range); };
}

bool MaterialTarget::layered() const { return material_.layers && !material_.layers->empty(); }

std::string MaterialTarget::describe() const { return describe_stack(material_); }

}  // namespace metalfit
