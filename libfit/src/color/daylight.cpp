#include "libfit/color/daylight.hpp"

#include <cmath>
#include <sstream>

#include "color/cie_table.hpp"
#include "libfit/base/errors.hpp"

namespace metalfit {

DaylightCoefficients daylight_coefficients(double T, DaylightRounding rounding) {
    if (!(T >= kDaylightMinKelvin && T <= kDaylightMaxKelvin)) {
        std::ostringstream s;
        s << "daylight at " << T << " K is outside the CIE's 4000–25000 K";
        throw UsageError(s.str());
    }
    DaylightCoefficients c;
    c.kelvin = T;
    const double T2 = T * T, T3 = T2 * T;
    c.x = T <= 7000.0 ? -4.6070e9 / T3 + 2.9678e6 / T2 + 0.09911e3 / T + 0.244063
                      : -2.0064e9 / T3 + 1.9018e6 / T2 + 0.24748e3 / T + 0.237040;
    c.y = -3.000 * c.x * c.x + 2.870 * c.x - 0.275;
    const double M = 0.0241 + 0.2562 * c.x - 0.7341 * c.y;
    c.M1 = (-1.3515 - 1.7703 * c.x + 5.9114 * c.y) / M;
    c.M2 = (0.0300 - 31.4424 * c.x + 30.0717 * c.y) / M;
    if (rounding == DaylightRounding::cie_three_decimals) {
        c.M1 = std::round(c.M1 * 1000.0) / 1000.0;
        c.M2 = std::round(c.M2 * 1000.0) / 1000.0;
    }
    return c;
}

DaylightBasis DaylightBasis::load(const std::filesystem::path& file) {
    const detail::CieTable table = detail::read_cie_table(file, 3);
    DaylightBasis b;
    if (table.size() < 2) throw InputError({file}, "needs at least two rows");
    b.first_nm = table.begin()->first;
    int expected = b.first_nm;
    for (const auto& [nm, v] : table) {
        if (nm != expected)
            throw InputError({file}, "expected a row at " + std::to_string(expected) + " nm (5 nm steps)");
        b.S.push_back({v[0], v[1], v[2]});
        expected += b.step_nm;
    }
    return b;
}

DenseSpectrum<double> daylight_spectrum(const DaylightBasis& basis, const DaylightCoefficients& c) {
    std::vector<double> at5;
    at5.reserve(basis.S.size());
    for (const auto& s : basis.S) at5.push_back(s[0] + c.M1 * s[1] + c.M2 * s[2]);
    return DenseSpectrum<double>::sampled(basis.first_nm, basis.last_nm(), [&](int nm) {
        const int offset = nm - basis.first_nm;
        const std::size_t i = static_cast<std::size_t>(offset / basis.step_nm);
        const int within = offset % basis.step_nm;
        if (within == 0) return at5[i];
        const double t = static_cast<double>(within) / basis.step_nm;
        return at5[i] + (at5[i + 1] - at5[i]) * t;
    });
}

}  // namespace metalfit
