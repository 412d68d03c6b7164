#include "libfit/color/illuminant.hpp"

#include <algorithm>
#include <cctype>

#include "color/cie_table.hpp"
#include "libfit/base/errors.hpp"
#include "libfit/color/daylight.hpp"
#include "libfit/spectral/spectrum.hpp"

namespace metalfit {

Illuminant Illuminant::parse(std::string_view s) {
    if (s == "D65") return D65;
    if (s == "D50") return D50;
    if (s == "A") return A;
    if (s == "E") return E;
    const std::string name(s);
    const bool digits = s.size() >= 3 && s.front() == 'D' && std::all_of(s.begin() + 1, s.end(), [](char c) {
                            return std::isdigit(static_cast<unsigned char>(c));
                        });
    const std::size_t n = s.size() - 1;
    if (!digits || (n != 2 && n != 4 && n != 5))
        throw UsageError("unknown illuminant '" + name +
                         "' (expected D65, D50, D55, D60, D75, A, E or D<T> with T in kelvin, e.g. D6500)");
    const double number = std::stod(name.substr(1));
    const double kelvin = n == 2 ? number * 100.0 * kDaylightC2Correction : number;
    daylight_coefficients(kelvin);  // checks the range
    return Illuminant(Kind::daylight, name, kelvin);
}

Illuminant parse_illuminant(std::string_view s) { return Illuminant::parse(s); }

DenseSpectrum<double> Illuminant::spectrum(const std::filesystem::path& data_dir) const {
    const auto cie = data_dir / "cie";
    switch (kind_) {
        case Kind::equal_energy:
            return DenseSpectrum<double>(static_cast<int>(kVisibleRange.min_nm), static_cast<int>(kVisibleRange.max_nm),
                                         1.0);
        case Kind::daylight:
            return daylight_spectrum(DaylightBasis::load(cie / "cie_daylight_basis_S0S1S2.csv"),
                                     daylight_coefficients(kelvin_));
        case Kind::tabulated: break;
    }
    const auto file = cie / ("cie_illuminant_" + name_ + ".csv");
    const detail::CieTable table = detail::read_cie_table(file, 1);
    if (table.empty()) throw InputError({file}, "no rows");
    const int first = table.begin()->first, last = table.rbegin()->first;
    return DenseSpectrum<double>::sampled(first, last,
                                          [&](int nm) { return detail::cie_row(table, nm, file, "1 nm steps")[0]; });
}

}  // namespace metalfit
