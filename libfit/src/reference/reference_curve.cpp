#include "libfit/reference/reference_curve.hpp"

#include <algorithm>
#include <sstream>

#include "libfit/base/errors.hpp"
#include "libfit/optics/fresnel.hpp"

namespace metalfit {
namespace {

void require_visible_coverage(const Material& m, const SpectralOptions& options) {
    if (options.out_of_range == OutOfRange::clamp) return;
    for (const auto& [curve, what] : {std::pair{&m.index.n, "n"}, std::pair{&m.index.k, "k"}}) {
        const WavelengthRange r = curve->range();
        if (r.covers(kVisibleRange)) continue;
        std::ostringstream s;
        s << what << " covers " << r.min_nm << "–" << r.max_nm << " nm, but colour needs " << kVisibleRange.min_nm
          << "–" << kVisibleRange.max_nm << " nm (--extrapolate holds the end values outside the measured range)";
        throw InputError({m.provenance.file, 0, "DATA"}, s.str());
    }
}

std::string nm(double v) {
    std::ostringstream s;
    s << v;
    return s.str();
}

}  // namespace

std::vector<std::string> held_constant_ranges(const Material& m, const WavelengthRange& needed, const SpectralOptions& options) {
    std::vector<std::string> notes;
    if (options.out_of_range != OutOfRange::clamp) return notes;
    for (const auto& [curve, what] : {std::pair{&m.index.n, "n"}, std::pair{&m.index.k, "k"}}) {
        const WavelengthRange r = curve->range();
        const std::string measured = " (--extrapolate; measured " + nm(r.min_nm) + "–" + nm(r.max_nm) + " nm)";
        if (r.min_nm > needed.min_nm)
            notes.push_back(std::string(what) + " held at its " + nm(r.min_nm) + " nm value over " + nm(needed.min_nm) + "–" +
                            nm(std::min(r.min_nm, needed.max_nm)) + " nm" + measured);
        if (r.max_nm < needed.max_nm)
            notes.push_back(std::string(what) + " held at its " + nm(r.max_nm) + " nm value over " +
                            nm(std::max(r.max_nm, needed.min_nm)) + "–" + nm(needed.max_nm) + " nm" + measured);
    }
    return notes;
}

ReferenceCurve::ReferenceCurve(const Material& material, const Colorimetry& colorimetry,
                               ColorSpaceConverter converter, SpectralOptions options)
    : colorimetry_(colorimetry), converter_(std::move(converter)) {
    require_visible_coverage(material, options);
    const DenseSpectrum<XYZ>& grid = colorimetry_.weights();
    eta_ = DenseSpectrum<std::complex<double>>::sampled(grid.first_nm(), grid.last_nm(), [&](int nm) {
        return material.index(nm, options.interpolation, options.out_of_range);
    });
    raw_white_ = converter_(colorimetry_.white());
    held_constant_ = held_constant_ranges(material, {double(grid.first_nm()), double(grid.last_nm())}, options);
}

XYZ ReferenceCurve::xyz(double mu) const {
    return colorimetry_.integrate(eta_.map([mu](const std::complex<double>& eta) { return fresnel(mu, eta); }));
}

RGB ReferenceCurve::operator()(double mu) const { return converter_(xyz(mu)) / raw_white_; }

}  // namespace metalfit
