// CIE daylight illuminants D<T> from the basis S₀, S₁, S₂ (CIE 015:2018, Colorimetry, 4th edition, §4.1.2):
// x_D(T), y_D = −3.000 x_D² + 2.870 x_D − 0.275, M₁ and M₂ rounded to three decimals,
// S(λ) = S₀(λ) + M₁ S₁(λ) + M₂ S₂(λ) at the basis' 5 nm, linearly interpolated to 1 nm.
#pragma once

#include <array>
#include <filesystem>
#include <vector>

#include "libfit/spectral/dense_spectrum.hpp"

namespace metalfit {

// The CIE's nominal daylight names (D50, D55, D65, D75) carry temperatures of the old radiation constant
// c₂ = 1.4380e-2 m·K; on today's scale (1.4388e-2) T = nominal × 1.4388/1.4380 (D65: 6503.6 K).
inline constexpr double kDaylightC2Correction = 1.4388 / 1.4380;
inline constexpr double kDaylightMinKelvin = 4000.0, kDaylightMaxKelvin = 25000.0;

struct DaylightCoefficients {
    double kelvin = 0.0;
    double x = 0.0, y = 0.0;  // chromaticity of the daylight locus at T
    double M1 = 0.0, M2 = 0.0;
};

enum class DaylightRounding { cie_three_decimals, unrounded };

// Throws UsageError outside 4000–25000 K (the range of the CIE's x_D formulas).
DaylightCoefficients daylight_coefficients(double kelvin,
                                           DaylightRounding rounding = DaylightRounding::cie_three_decimals);

// S₀, S₁, S₂ at 5 nm (data/cie/cie_daylight_basis_S0S1S2.csv, 300–830 nm).
struct DaylightBasis {
    int first_nm = 300;
    int step_nm = 5;
    std::vector<std::array<double, 3>> S;  // S₀, S₁, S₂ at first_nm + i·step_nm

    // Throws InputError naming the file for a missing file, a bad row or a grid that is not 5 nm.
    static DaylightBasis load(const std::filesystem::path& file);
    int last_nm() const { return first_nm + step_nm * (static_cast<int>(S.size()) - 1); }
};

// The relative spectral power at 1 nm over the basis' range (linear interpolation between its 5 nm points).
DenseSpectrum<double> daylight_spectrum(const DaylightBasis& basis, const DaylightCoefficients& coefficients);

}  // namespace metalfit
