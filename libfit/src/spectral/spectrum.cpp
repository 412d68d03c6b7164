#include "libfit/spectral/spectrum.hpp"

#include <algorithm>
#include <cmath>
#include <sstream>

namespace metalfit {
namespace {

std::string range_message(double nm, WavelengthRange r) {
    std::ostringstream s;
    s << "wavelength " << nm << " nm is outside the data range " << r.min_nm << "–" << r.max_nm << " nm";
    return s.str();
}

// Fritsch–Carlson monotone derivatives (the PCHIP of Fritsch & Butland / SciPy's
// PchipInterpolator): zero at local extrema, weighted harmonic mean of the secants elsewhere,
// shape-preserving three-point formula at the ends.
std::vector<double> pchip_slopes(const std::vector<double>& x, const std::vector<double>& y) {
    const std::size_t n = x.size();
    std::vector<double> d(n, 0.0);
    if (n < 2) return d;
    std::vector<double> h(n - 1), delta(n - 1);
    for (std::size_t i = 0; i + 1 < n; ++i) {
        h[i] = x[i + 1] - x[i];
        delta[i] = (y[i + 1] - y[i]) / h[i];
    }
    if (n == 2) {
        d[0] = d[1] = delta[0];
        return d;
    }
    for (std::size_t i = 1; i + 1 < n; ++i) {
        if (delta[i - 1] * delta[i] <= 0.0) continue;
        const double w1 = 2.0 * h[i] + h[i - 1];
        const double w2 = h[i] + 2.0 * h[i - 1];
        d[i] = (w1 + w2) / (w1 / delta[i - 1] + w2 / delta[i]);
    }
    auto edge = [](double h0, double h1, double m0, double m1) {
        double e = ((2.0 * h0 + h1) * m0 - h0 * m1) / (h0 + h1);
        if (e * m0 <= 0.0) return 0.0;
        if (m0 * m1 <= 0.0 && std::abs(e) > std::abs(3.0 * m0)) return 3.0 * m0;
        return e;
    };
    d[0] = edge(h[0], h[1], delta[0], delta[1]);
    d[n - 1] = edge(h[n - 2], h[n - 3], delta[n - 2], delta[n - 3]);
    return d;
}

}  // namespace

SpectrumRangeError::SpectrumRangeError(double nm, WavelengthRange r)
    : std::domain_error(range_message(nm, r)), requested_nm(nm), range(r) {}

Spectrum::Spectrum(std::vector<SpectrumSample> samples) {
    if (samples.empty()) throw std::invalid_argument("a spectrum needs at least one sample");
    for (const auto& s : samples)
        if (!std::isfinite(s.wavelength_nm) || !std::isfinite(s.value))
            throw std::invalid_argument("a spectrum sample is not a finite number");
    std::stable_sort(samples.begin(), samples.end(),
                     [](const auto& a, const auto& b) { return a.wavelength_nm < b.wavelength_nm; });
    for (std::size_t i = 0; i < samples.size();) {
        std::size_t j = i;
        double sum = 0.0;
        bool conflict = false;
        for (; j < samples.size() && samples[j].wavelength_nm == samples[i].wavelength_nm; ++j) {
            sum += samples[j].value;
            conflict = conflict || samples[j].value != samples[i].value;
        }
        const std::size_t repeats = j - i - 1;
        if (conflict)
            conflicting_duplicates_ += repeats;
        else
            identical_duplicates_ += repeats;
        wavelengths_.push_back(samples[i].wavelength_nm);
        values_.push_back(sum / static_cast<double>(j - i));
        i = j;
    }
    pchip_slopes_ = pchip_slopes(wavelengths_, values_);
}

std::size_t Spectrum::count_in(const WavelengthRange& r) const {
    return static_cast<std::size_t>(
        std::count_if(wavelengths_.begin(), wavelengths_.end(), [&](double w) { return r.contains(w); }));
}

double Spectrum::operator()(double nm, Interpolation interpolation, OutOfRange out_of_range) const {
    if (!range().contains(nm)) {
        if (out_of_range == OutOfRange::error || std::isnan(nm)) throw SpectrumRangeError(nm, range());
        return nm < wavelengths_.front() ? values_.front() : values_.back();
    }
    if (wavelengths_.size() == 1) return values_.front();
    // i: the interval [x_i, x_{i+1}] containing nm.
    auto upper = std::upper_bound(wavelengths_.begin(), wavelengths_.end(), nm);
    std::size_t i = static_cast<std::size_t>(upper - wavelengths_.begin());
    i = std::min(i == 0 ? 0 : i - 1, wavelengths_.size() - 2);
    return interpolation == Interpolation::linear ? linear(i, nm) : pchip(i, nm);
}

double Spectrum::linear(std::size_t i, double nm) const {
    const double t = (nm - wavelengths_[i]) / (wavelengths_[i + 1] - wavelengths_[i]);
    return values_[i] + t * (values_[i + 1] - values_[i]);
}

double Spectrum::pchip(std::size_t i, double nm) const {
    const double h = wavelengths_[i + 1] - wavelengths_[i];
    const double t = (nm - wavelengths_[i]) / h;
    const double t2 = t * t, t3 = t2 * t;
    const double h00 = 2 * t3 - 3 * t2 + 1, h10 = t3 - 2 * t2 + t;
    const double h01 = -2 * t3 + 3 * t2, h11 = t3 - t2;
    return h00 * values_[i] + h10 * h * pchip_slopes_[i] + h01 * values_[i + 1] + h11 * h * pchip_slopes_[i + 1];
}

}  // namespace metalfit
