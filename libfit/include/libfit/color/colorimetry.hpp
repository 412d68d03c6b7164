// Colorimetry: spectral reflectance → XYZ under an illuminant and a standard observer.
#pragma once

#include <filesystem>
#include <span>
#include <string>
#include <string_view>
#include <vector>

#include "libfit/color/color.hpp"
#include "libfit/spectral/dense_spectrum.hpp"

namespace metalfit {

enum class Observer { cie1931_2deg, cie1964_10deg };
enum class Illuminant { D65, A, E };

Observer parse_observer(std::string_view s);      // "1931" | "1964"; UsageError otherwise
Illuminant parse_illuminant(std::string_view s);  // "D65" | "A" | "E"; UsageError otherwise
std::string to_string(Observer o);                // "CIE 1931 2°" / "CIE 1964 10°"
std::string to_string(Illuminant i);              // "D65" / "A" / "E"

// Weights S(λ)·x̄(λ), S(λ)·ȳ(λ), S(λ)·z̄(λ) at 1 nm over 360–830 nm, normalised so that a perfect
// reflector (R ≡ 1) has Y = 1. XYZ = Σ_λ R(λ)·w(λ) (the CIE's 1 nm summation).
class Colorimetry {
public:
    // Reads the CMF and illuminant tables from <data_dir>/cie. Throws InputError.
    static Colorimetry load(const std::filesystem::path& data_dir, Observer observer,
                            Illuminant illuminant);

    // The weights S·x̄, S·ȳ, S·z̄ on the 1 nm grid of 360–830 nm; a reflectance to integrate lies on the same grid.
    const DenseSpectrum<XYZ>& weights() const { return weights_; }
    // Σ_λ R(λ) w(λ); throws std::invalid_argument for a reflectance on another grid.
    XYZ integrate(const DenseSpectrum<double>& reflectance) const;
    // XYZ of the perfect reflector under this illuminant (Y = 1).
    XYZ white() const { return white_; }
    Observer observer() const { return observer_; }
    Illuminant illuminant() const { return illuminant_; }

private:
    Observer observer_{};
    Illuminant illuminant_{};
    DenseSpectrum<XYZ> weights_;
    XYZ white_;
};

}  // namespace metalfit
