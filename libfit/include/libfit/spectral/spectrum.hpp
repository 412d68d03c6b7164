// Spectrum: a tabulated function of vacuum wavelength in nanometres.
#pragma once

#include <cstddef>
#include <span>
#include <stdexcept>
#include <string>
#include <vector>

#include "libfit/base/enum_names.hpp"

namespace metalfit {

enum class Interpolation { linear, pchip };
// "linear" / "pchip", as records and options (--interp) spell them.
inline constexpr EnumNames kInterpolationNames{"interpolation", KnownNamesWording::alternatives,
                                               std::array{EnumName<Interpolation>{Interpolation::linear, "linear"},
                                                          EnumName<Interpolation>{Interpolation::pchip, "pchip"}}};
inline std::string to_string(Interpolation i) { return std::string(kInterpolationNames.name(i)); }
// What to do when asked for a wavelength outside the measured range.
enum class OutOfRange { error, clamp };
// "error" / "clamp", as records spell them.
inline constexpr EnumNames kOutOfRangeNames{
    "out-of-range rule", KnownNamesWording::alternatives,
    std::array{EnumName<OutOfRange>{OutOfRange::error, "error"}, EnumName<OutOfRange>{OutOfRange::clamp, "clamp"}}};
inline std::string to_string(OutOfRange o) { return std::string(kOutOfRangeNames.name(o)); }

struct WavelengthRange {
    double min_nm = 0.0;
    double max_nm = 0.0;
    bool contains(double nm) const { return nm >= min_nm && nm <= max_nm; }
    bool covers(const WavelengthRange& other) const { return min_nm <= other.min_nm && max_nm >= other.max_nm; }
};

// The visible range every colour computation integrates over (1 nm steps).
inline constexpr WavelengthRange kVisibleRange{360.0, 830.0};

struct SpectrumSample {
    double wavelength_nm;
    double value;
};

// Thrown when a spectrum is evaluated outside its range without OutOfRange::clamp.
class SpectrumRangeError : public std::domain_error {
public:
    SpectrumRangeError(double requested_nm, WavelengthRange range);
    double requested_nm;
    WavelengthRange range;
};

// Sorted, de-duplicated samples. Construction rule for repeated wavelengths:
//  - rows with identical values are dropped (counted in identical_duplicates());
//  - rows with different values at the same wavelength are replaced by their mean
//    (counted in conflicting_duplicates(); importers turn that into a warning).
class Spectrum {
public:
    // Throws std::invalid_argument when samples is empty or holds a non-finite number.
    explicit Spectrum(std::vector<SpectrumSample> samples);

    double operator()(double nm, Interpolation interpolation = Interpolation::linear,
                      OutOfRange out_of_range = OutOfRange::error) const;

    WavelengthRange range() const { return {wavelengths_.front(), wavelengths_.back()}; }
    std::size_t size() const { return wavelengths_.size(); }
    std::span<const double> wavelengths() const { return wavelengths_; }
    std::span<const double> values() const { return values_; }
    std::size_t identical_duplicates() const { return identical_duplicates_; }
    std::size_t conflicting_duplicates() const { return conflicting_duplicates_; }
    // Number of samples with wavelength inside `range` (inclusive).
    std::size_t count_in(const WavelengthRange& range) const;

private:
    double linear(std::size_t i, double nm) const;
    double pchip(std::size_t i, double nm) const;

    std::vector<double> wavelengths_;
    std::vector<double> values_;
    std::vector<double> pchip_slopes_;  // Fritsch–Carlson derivatives at the samples
    std::size_t identical_duplicates_ = 0;
    std::size_t conflicting_duplicates_ = 0;
};

}  // namespace metalfit
