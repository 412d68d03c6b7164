// ComplexIndex: the spectral complex refractive index η(λ) = n(λ) + i k(λ) of a material.
#pragma once

#include <complex>
#include <string>
#include <variant>

#include "libfit/spectral/dispersion_formula.hpp"
#include "libfit/spectral/spectrum.hpp"

namespace metalfit {

// A wavelength-independent value (k = 0 of a transparent material).
struct ConstantSpectrum {
    double value = 0.0;
};

// One real spectral component (n or k), tabulated, analytic or constant.
class SpectralCurve {
public:
    SpectralCurve() : curve_(ConstantSpectrum{}) {}
    SpectralCurve(Spectrum s) : curve_(std::move(s)) {}
    SpectralCurve(SellmeierFormula f) : curve_(std::move(f)) {}
    SpectralCurve(ConstantSpectrum c) : curve_(c) {}

    double operator()(double nm, Interpolation interpolation, OutOfRange out_of_range) const;
    // The wavelengths where the curve is defined (a constant is defined everywhere).
    WavelengthRange range() const;
    // Sample count for tabulated curves, 0 otherwise.
    std::size_t tabulated_points_in(const WavelengthRange& r) const;
    const Spectrum* tabulated() const { return std::get_if<Spectrum>(&curve_); }
    std::string kind() const;  // "tabulated", "formula 1", "formula 2", "constant"

private:
    std::variant<Spectrum, SellmeierFormula, ConstantSpectrum> curve_;
};

struct ComplexIndex {
    SpectralCurve n;
    SpectralCurve k;

    std::complex<double> operator()(double nm, Interpolation interpolation = Interpolation::linear,
                                    OutOfRange out_of_range = OutOfRange::error) const {
        return {n(nm, interpolation, out_of_range), k(nm, interpolation, out_of_range)};
    }
    // Where both n and k are defined.
    WavelengthRange range() const;
};

}  // namespace metalfit
