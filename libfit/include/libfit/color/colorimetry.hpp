// Colorimetry: spectral reflectance → XYZ under an illuminant and a standard observer, adapted to the D65
// connection white of the colour pipeline when the illuminant's white differs (docs/colour.md).
#pragma once

#include <filesystem>
#include <span>
#include <string>
#include <string_view>
#include <vector>

#include "libfit/base/enum_names.hpp"
#include "libfit/color/chromatic_adaptation.hpp"
#include "libfit/color/color.hpp"
#include "libfit/color/illuminant.hpp"
#include "libfit/spectral/dense_spectrum.hpp"

namespace metalfit {

enum class Observer { cie1931_2deg, cie1964_10deg, cie2015_2deg, cie2015_10deg };
// The --cmf values.
inline constexpr EnumNames kObserverNames{"observer", KnownNamesWording::expected,
                                          std::array{EnumName<Observer>{Observer::cie1931_2deg, "1931"},
                                                     EnumName<Observer>{Observer::cie1964_10deg, "1964"},
                                                     EnumName<Observer>{Observer::cie2015_2deg, "2015-2"},
                                                     EnumName<Observer>{Observer::cie2015_10deg, "2015-10"}}};

Observer parse_observer(std::string_view s);  // "1931" | "1964" | "2015-2" | "2015-10"; UsageError otherwise
std::string to_string(Observer o);            // "CIE 1931 2°" / "CIE 1964 10°" / "CIE 2015 2°" / "CIE 2015 10°"
std::string option_name(Observer o);          // "1931" / "1964" / "2015-2" / "2015-10" (the --cmf value)

// The observer's x̄ ȳ z̄ at 1 nm over 360–830 nm. The CIE 2015 tables start at 390 nm (CIE 170-2 has no values
// below); their 360–389 nm are zeros, which are not CIE values. Throws InputError naming the file.
DenseSpectrum<XYZ> colour_matching_functions(const std::filesystem::path& data_dir, Observer observer);

// The connection white: XYZ enters OCIO through the role cie_xyz_d65_interchange, so every illuminant's white is
// adapted to the white of CIE D65 under the same observer. D65 itself is not adapted (nothing to do).
inline const Illuminant& connection_illuminant() { return Illuminant::D65; }

// Weights S(λ)·x̄(λ), S(λ)·ȳ(λ), S(λ)·z̄(λ) at 1 nm over 360–830 nm, normalised so that a perfect
// reflector (R ≡ 1) has Y = 1, then multiplied by the chromatic adaptation matrix M (the identity for D65 or
// `none`). XYZ = Σ_λ R(λ)·w(λ) (the CIE's 1 nm summation).
class Colorimetry {
public:
    // Reads the CMF and illuminant tables from <data_dir>/cie. Throws InputError.
    static Colorimetry load(const std::filesystem::path& data_dir, Observer observer, const Illuminant& illuminant,
                            Adaptation adaptation = Adaptation::bradford);

    // The weights on the 1 nm grid of 360–830 nm; a reflectance to integrate lies on the same grid.
    const DenseSpectrum<XYZ>& weights() const { return weights_; }
    // Σ_λ R(λ) w(λ); throws std::invalid_argument for a reflectance on another grid.
    XYZ integrate(const DenseSpectrum<double>& reflectance) const;
    // XYZ of the perfect reflector, after adaptation (the connection white when adapted; Y = 1).
    XYZ white() const { return white_; }
    // XYZ of the perfect reflector under the illuminant, before adaptation (Y = 1).
    XYZ illuminant_white() const { return illuminant_white_; }
    Observer observer() const { return observer_; }
    const Illuminant& illuminant() const { return illuminant_; }
    Adaptation adaptation() const { return adaptation_; }  // as asked
    bool adapted() const { return adapted_; }              // false for D65, `none` or equal whites
    const Matrix3& adaptation_matrix() const { return matrix_; }

private:
    Colorimetry(Observer observer, Illuminant illuminant, Adaptation adaptation)
        : observer_(observer), illuminant_(std::move(illuminant)), adaptation_(adaptation) {}
    Observer observer_;
    Illuminant illuminant_;
    Adaptation adaptation_;
    bool adapted_ = false;
    Matrix3 matrix_ = Matrix3::identity();
    DenseSpectrum<XYZ> weights_;
    XYZ white_, illuminant_white_;
};

// One line for records and headers: "bradford, A white → D65 white", "bradford (not needed: D65)" or "none".
std::string describe_adaptation(Adaptation adaptation, bool adapted, const Illuminant& illuminant);

}  // namespace metalfit
