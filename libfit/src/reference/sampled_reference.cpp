#include "libfit/reference/sampled_reference.hpp"

#include <cmath>
#include <cstdio>
#include <stdexcept>

#include "libfit/base/errors.hpp"
#include "libfit/base/number_text.hpp"
#include "libfit/base/quadrature.hpp"

namespace metalfit {

std::string to_string(ErrorMetric m) { return std::string(kErrorMetricNames.name(m)); }
std::string to_string(AngularWeight w) { return std::string(kAngularWeightNames.name(w)); }

ErrorMetric parse_error_metric(const std::string& text) { return kErrorMetricNames.parse(text); }

AngularWeight parse_angular_weight(const std::string& text) { return kAngularWeightNames.parse(text); }

SampledReference::SampledReference(const ReferenceCurve& curve, const ErrorSettings& settings)
    : converter_(curve.converter()), raw_white_(curve.raw_white()), settings_(settings) {
    if (settings.nodes < 2 || settings.nodes > 4096)
        throw UsageError("the number of quadrature nodes must be in [2, 4096], got " + std::to_string(settings.nodes));
    white_ = converter_.to_xyz(raw_white_);
    for (const QuadratureNode& q : gauss_legendre_unit(settings.nodes)) {
        const double w = settings.weight == AngularWeight::uniform ? 1.0 : 2.0 * q.mu;
        nodes_.push_back(Sample{q.mu, q.weight * w, q.weight * 2.0 * q.mu, {}, {}});
    }
    for (int i = 0; i <= kDenseIntervals; ++i) dense_.push_back(Sample{double(i) / kDenseIntervals, 0.0, 0.0, {}, {}});
    // Every μ in one batch (the curve evaluates them together, with the same values as one at a time).
    for (const auto* samples : {&nodes_, &dense_})
        for (const Sample& s : *samples) mu_.push_back(s.mu);
    const std::vector<RGB> values = curve(std::span<const double>(mu_));
    const std::vector<Lab> labs = lab(values);
    std::size_t next = 0;
    for (auto* samples : {&nodes_, &dense_})
        for (Sample& s : *samples) {
            s.value = values[next];
            s.lab = labs[next++];
        }

    for (const auto* samples : {&nodes_, &dense_})
        for (const Sample& s : *samples)
            for (int c = 0; c < 3 && !rel_undefined_; ++c)
                if (!(s.value[c] > 0.0))
                    rel_undefined_ = "the reference's " + std::string(kChannelNames[c]) + " channel is " +
                                     significant_text(s.value[c], 3) + " at mu = " + significant_text(s.mu, 4);
}

std::vector<Lab> SampledReference::lab(std::span<const RGB> balanced) const {
    std::vector<RGB> raw;
    raw.reserve(balanced.size());
    for (const RGB& c : balanced) raw.emplace_back(c.r * raw_white_.r, c.g * raw_white_.g, c.b * raw_white_.b);
    std::vector<Lab> labs;
    labs.reserve(balanced.size());
    for (const XYZ& xyz : converter_.to_xyz(std::span<const RGB>(raw))) labs.push_back(xyz_to_lab(xyz, white_));
    return labs;
}

ChannelTarget SampledReference::target(int channel) const {
    const bool rel = settings_.metric == ErrorMetric::rel;
    if (rel && rel_undefined_) throw std::logic_error("relative metric undefined: " + *rel_undefined_);
    ChannelTarget t;
    for (const Sample& s : nodes_) {
        const double value = s.value[channel];
        t.mu.push_back(s.mu);
        t.value.push_back(value);
        t.scale.push_back(std::sqrt(s.weight) / (rel ? value : 1.0));
    }
    return t;
}

}  // namespace metalfit
