// Illuminants: the CIE's tables (D65, D50, A), equal energy (E) and daylight D<T> computed from S₀, S₁, S₂.
#pragma once

#include <filesystem>
#include <string>
#include <string_view>

#include "libfit/spectral/dense_spectrum.hpp"

namespace metalfit {

class Illuminant {
public:
    enum class Kind { tabulated, daylight, equal_energy };

    // The named ones: `Illuminant::D65` etc. (D65, D50, A are the CIE's 1 nm tables).
    static const Illuminant D65, D50, A, E;

    // "D65" | "D50" | "A" | "E" | "Dxx" (a nominal CIE name: T = xx·100 K × 1.4388/1.4380, e.g. D55, D60, D75) |
    // "D<T>" with T in kelvin on today's scale, four or five digits (D6500, D5003): computed daylight.
    // UsageError otherwise, or for T outside 4000–25000 K.
    static Illuminant parse(std::string_view name);

    Kind kind() const { return kind_; }
    const std::string& name() const { return name_; }
    double kelvin() const { return kelvin_; }  // daylight only: the T used (after the c₂ correction)

    // The relative spectral power at 1 nm (E: 1 everywhere over 360–830 nm), read from <data_dir>/cie.
    // Throws InputError naming the file.
    DenseSpectrum<double> spectrum(const std::filesystem::path& data_dir) const;

    friend bool operator==(const Illuminant& a, const Illuminant& b) { return a.name_ == b.name_; }

private:
    Illuminant(Kind kind, std::string name, double kelvin = 0.0)
        : kind_(kind), name_(std::move(name)), kelvin_(kelvin) {}
    Kind kind_;
    std::string name_;
    double kelvin_;
};

inline const Illuminant Illuminant::D65{Illuminant::Kind::tabulated, "D65"};
inline const Illuminant Illuminant::D50{Illuminant::Kind::tabulated, "D50"};
inline const Illuminant Illuminant::A{Illuminant::Kind::tabulated, "A"};
inline const Illuminant Illuminant::E{Illuminant::Kind::equal_energy, "E"};

Illuminant parse_illuminant(std::string_view s);  // Illuminant::parse
inline std::string to_string(const Illuminant& i) { return i.name(); }

}  // namespace metalfit
