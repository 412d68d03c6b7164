#include "libfit/color/colorimetry.hpp"

#include <cmath>
#include <fstream>
#include <map>

#include "libfit/base/errors.hpp"
#include "libfit/spectral/spectrum.hpp"
#include "base/parse_number.hpp"

namespace metalfit {
namespace {

// A CIE table "wavelength_nm,c1[,c2,c3]" at integer wavelengths: wavelength → values.
std::map<int, std::vector<double>> read_cie_table(const std::filesystem::path& file, std::size_t columns) {
    std::ifstream in(file);
    if (!in) throw InputError({file}, "cannot open CIE table");
    std::map<int, std::vector<double>> rows;
    int line_number = 0;
    for (std::string raw; std::getline(in, raw);) {
        ++line_number;
        const auto line = detail::trim(raw);
        if (line.empty() || line_number == 1) continue;  // header
        const auto fields = detail::split_commas(line);
        if (fields.size() != columns + 1) throw InputError({file, line_number}, "expected " + std::to_string(columns + 1) + " fields");
        const std::vector<double> v = detail::parse_row(fields, {file, line_number});
        rows[static_cast<int>(std::lround(v[0]))] = std::vector<double>(v.begin() + 1, v.end());
    }
    return rows;
}

const std::vector<double>& at(const std::map<int, std::vector<double>>& table, int nm,
                              const std::filesystem::path& file) {
    const auto it = table.find(nm);
    if (it == table.end()) throw InputError({file}, "no row for " + std::to_string(nm) + " nm (360–830 nm at 1 nm steps needed)");
    return it->second;
}

}  // namespace

Observer parse_observer(std::string_view s) {
    if (s == "1931") return Observer::cie1931_2deg;
    if (s == "1964") return Observer::cie1964_10deg;
    throw UsageError("unknown observer '" + std::string(s) + "' (expected 1931 or 1964)");
}

Illuminant parse_illuminant(std::string_view s) {
    if (s == "D65") return Illuminant::D65;
    if (s == "A") return Illuminant::A;
    if (s == "E") return Illuminant::E;
    throw UsageError("unknown illuminant '" + std::string(s) + "' (expected D65, A or E)");
}

std::string to_string(Observer o) { return o == Observer::cie1931_2deg ? "CIE 1931 2°" : "CIE 1964 10°"; }

std::string to_string(Illuminant i) {
    switch (i) {
        case Illuminant::D65: return "D65";
        case Illuminant::A: return "A";
        case Illuminant::E: return "E";
    }
    return "?";
}

Colorimetry Colorimetry::load(const std::filesystem::path& data_dir, Observer observer, Illuminant illuminant) {
    const auto cie = data_dir / "cie";
    const auto cmf_file = cie / (observer == Observer::cie1931_2deg ? "cie1931_2deg_cmf.csv" : "cie1964_10deg_cmf.csv");
    const auto cmf = read_cie_table(cmf_file, 3);
    std::filesystem::path spd_file;
    std::map<int, std::vector<double>> spd;
    if (illuminant != Illuminant::E) {
        spd_file = cie / (illuminant == Illuminant::D65 ? "cie_illuminant_D65.csv" : "cie_illuminant_A.csv");
        spd = read_cie_table(spd_file, 1);
    }

    Colorimetry c;
    c.observer_ = observer;
    c.illuminant_ = illuminant;
    const int first = static_cast<int>(kVisibleRange.min_nm), last = static_cast<int>(kVisibleRange.max_nm);
    const DenseSpectrum<XYZ> weighted = DenseSpectrum<XYZ>::sampled(first, last, [&](int nm) {
        const auto& xyz = at(cmf, nm, cmf_file);
        const double s = illuminant == Illuminant::E ? 1.0 : at(spd, nm, spd_file)[0];
        return XYZ{s * xyz[0], s * xyz[1], s * xyz[2]};
    });
    double y_sum = 0.0;
    for (const XYZ& w : weighted.values()) y_sum += w.Y;
    c.weights_ = weighted.map([y_sum](const XYZ& w) { return w / y_sum; });
    c.white_ = c.integrate(DenseSpectrum<double>(first, last, 1.0));
    return c;
}

XYZ Colorimetry::integrate(const DenseSpectrum<double>& reflectance) const { return sum_of_products(reflectance, weights_); }

}  // namespace metalfit
