#include "libfit/color/colorimetry.hpp"

#include "color/cie_table.hpp"
#include "libfit/base/errors.hpp"
#include "libfit/spectral/spectrum.hpp"

namespace metalfit {
namespace {

constexpr int kFirstNm = static_cast<int>(kVisibleRange.min_nm), kLastNm = static_cast<int>(kVisibleRange.max_nm);

const char* cmf_file_name(Observer o) {
    switch (o) {
        case Observer::cie1931_2deg: return "cie1931_2deg_cmf.csv";
        case Observer::cie1964_10deg: return "cie1964_10deg_cmf.csv";
        case Observer::cie2015_2deg: return "cie2015_2deg_cmf.csv";
        case Observer::cie2015_10deg: return "cie2015_10deg_cmf.csv";
    }
    return "";
}

// The first wavelength of the observer's table; below it the functions are zero (CIE 2015: 390 nm).
int first_tabulated_nm(Observer o) {
    return o == Observer::cie2015_2deg || o == Observer::cie2015_10deg ? 390 : kFirstNm;
}

// S·x̄, S·ȳ, S·z̄ normalised to Y = 1 for the perfect reflector.
DenseSpectrum<XYZ> normalised_weights(const DenseSpectrum<XYZ>& cmf, const DenseSpectrum<double>& spd,
                                      const std::filesystem::path& data_dir, const Illuminant& illuminant) {
    if (spd.first_nm() > kFirstNm || spd.last_nm() < kLastNm)
        throw InputError({data_dir / "cie"}, "illuminant " + illuminant.name() + " covers " +
                                                 std::to_string(spd.first_nm()) + "–" + std::to_string(spd.last_nm()) +
                                                 " nm (360–830 nm needed)");
    const DenseSpectrum<XYZ> weighted = DenseSpectrum<XYZ>::sampled(kFirstNm, kLastNm, [&](int nm) {
        const XYZ& xyz = cmf.at_nm(nm);
        const double s = spd.at_nm(nm);
        return XYZ{s * xyz.X, s * xyz.Y, s * xyz.Z};
    });
    double y_sum = 0.0;
    for (const XYZ& w : weighted.values()) y_sum += w.Y;
    return weighted.map([y_sum](const XYZ& w) { return w / y_sum; });
}

XYZ sum(const DenseSpectrum<XYZ>& w) {
    return sum_of_products(DenseSpectrum<double>(w.first_nm(), w.last_nm(), 1.0), w);
}

}  // namespace

Observer parse_observer(std::string_view s) { return kObserverNames.parse(s); }

std::string to_string(Observer o) {
    switch (o) {
        case Observer::cie1931_2deg: return "CIE 1931 2°";
        case Observer::cie1964_10deg: return "CIE 1964 10°";
        case Observer::cie2015_2deg: return "CIE 2015 2°";
        case Observer::cie2015_10deg: return "CIE 2015 10°";
    }
    return "?";
}

std::string option_name(Observer o) { return std::string(kObserverNames.name(o)); }

DenseSpectrum<XYZ> colour_matching_functions(const std::filesystem::path& data_dir, Observer observer) {
    const auto file = data_dir / "cie" / cmf_file_name(observer);
    const detail::CieTable cmf = detail::read_cie_table(file, 3);
    const int first = first_tabulated_nm(observer);
    const std::string needed = std::to_string(first) + "–830 nm at 1 nm steps";
    return DenseSpectrum<XYZ>::sampled(kFirstNm, kLastNm, [&](int nm) {
        if (nm < first) return XYZ{};  // not tabulated by the CIE: zero
        const auto& v = detail::cie_row(cmf, nm, file, needed);
        return XYZ{v[0], v[1], v[2]};
    });
}

Colorimetry Colorimetry::load(const std::filesystem::path& data_dir, Observer observer, const Illuminant& illuminant,
                              Adaptation adaptation) {
    Colorimetry c(observer, illuminant, adaptation);
    const DenseSpectrum<XYZ> cmf = colour_matching_functions(data_dir, observer);
    c.weights_ = normalised_weights(cmf, illuminant.spectrum(data_dir), data_dir, illuminant);
    c.illuminant_white_ = sum(c.weights_);
    if (adaptation != Adaptation::none && !(illuminant == connection_illuminant())) {
        const XYZ target =
            sum(normalised_weights(cmf, connection_illuminant().spectrum(data_dir), data_dir, connection_illuminant()));
        c.matrix_ = metalfit::adaptation_matrix(adaptation, c.illuminant_white_, target);
        c.adapted_ = !(c.matrix_ == Matrix3::identity());
        if (c.adapted_) c.weights_ = c.weights_.map([&](const XYZ& w) { return c.matrix_ * w; });
    }
    c.white_ = c.integrate(DenseSpectrum<double>(kFirstNm, kLastNm, 1.0));
    return c;
}

std::string describe_adaptation(Adaptation adaptation, bool adapted, const Illuminant& illuminant) {
    if (adaptation == Adaptation::none) return "none";
    if (adapted)
        return to_string(adaptation) + ", " + illuminant.name() + " white → " + connection_illuminant().name() +
               " white";
    return to_string(adaptation) + " (not needed: " + illuminant.name() + ")";
}

XYZ Colorimetry::integrate(const DenseSpectrum<double>& reflectance) const {
    return sum_of_products(reflectance, weights_);
}

}  // namespace metalfit
