#include "libfit/reference/sampled_reference.hpp"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <memory>
#include <stdexcept>
#include <utility>

#include "libfit/base/errors.hpp"
#include "libfit/base/number_text.hpp"
#include "libfit/base/quadrature.hpp"

namespace metalfit {

namespace {
// The grid is sampled in aligned blocks of this many points: as many μ as the reference curve integrates at once, for
// the cost of one (ReferenceCurve's lanes).
constexpr int kGridBlock = 8;
}  // namespace

std::string to_string(ErrorMetric m) { return std::string(kErrorMetricNames.name(m)); }
std::string to_string(AngularWeight w) { return std::string(kAngularWeightNames.name(w)); }

ErrorMetric parse_error_metric(const std::string& text) { return kErrorMetricNames.parse(text); }

AngularWeight parse_angular_weight(const std::string& text) { return kAngularWeightNames.parse(text); }

SampledReference::SampledReference(const ReferenceCurve& curve, const ErrorSettings& settings)
    : SampledReference(
          [copy = std::make_shared<const ReferenceCurve>(curve)](std::span<const double> mu) { return (*copy)(mu); },
          curve.converter(), curve.raw_white(), settings) {}

SampledReference::SampledReference(Curve curve, ColorSpaceConverter converter, RGB raw_white,
                                   const ErrorSettings& settings)
    : curve_(std::move(curve)), converter_(std::move(converter)), raw_white_(raw_white), settings_(settings) {
    if (settings.nodes < 2 || settings.nodes > 4096)
        throw UsageError("the number of quadrature nodes must be in [2, 4096], got " + std::to_string(settings.nodes));
    white_ = converter_.to_xyz(raw_white_);
    for (const QuadratureNode& q : gauss_legendre_unit(settings.nodes)) {
        const double w = settings.weight == AngularWeight::uniform ? 1.0 : 2.0 * q.mu;
        nodes_.push_back(Sample{q.mu, q.weight * w, q.weight * 2.0 * q.mu, {}, {}});
    }
    for (int i = 0; i <= kDenseIntervals; ++i) grid_.push_back(Sample{double(i) / kDenseIntervals, 0.0, 0.0, {}, {}});
    grid_sampled_.assign(grid_.size(), 0);
    // The nodes and both ends of the grid in one batch (the curve evaluates them together, with the same values as one
    // at a time).
    std::vector<double> mu;
    for (const Sample& s : nodes_) mu.push_back(s.mu);
    mu.push_back(grid_.front().mu);
    mu.push_back(grid_.back().mu);
    const std::vector<RGB> values = curve_(std::span<const double>(mu));
    if (values.size() != mu.size()) throw std::logic_error("a reference curve gave a value count other than asked");
    const std::vector<Lab> labs = lab(values);
    for (std::size_t i = 0; i < nodes_.size(); ++i) nodes_[i].value = values[i], nodes_[i].lab = labs[i];
    for (const std::size_t i : {std::size_t{0}, grid_.size() - 1}) {
        const std::size_t at = nodes_.size() + (i == 0 ? 0 : 1);
        grid_[i].value = values[at];
        grid_[i].lab = labs[at];
        grid_sampled_[i] = 1;
    }

    const auto first_not_positive = [&](std::span<const Sample> samples) {
        for (const Sample& s : samples)
            for (int c = 0; c < 3 && !rel_undefined_; ++c)
                if (!(s.value[c] > 0.0))
                    rel_undefined_ = "the reference's " + std::string(kChannelNames[c]) + " channel is " +
                                     significant_text(s.value[c], 3) + " at mu = " + significant_text(s.mu, 4);
    };
    first_not_positive(nodes_);
    // The grid is bracketed by the nodes unless they are few, or R comes near 0 (or below) at a node or an end; then
    // it is sampled whole, and checked in its order as the nodes are.
    whole_grid_ = settings.nodes < kFewestBracketingNodes;
    for (std::size_t i = 0; i < values.size() && !whole_grid_; ++i)
        for (int c = 0; c < 3; ++c)
            if (!(values[i][c] >= kNearZeroReference)) whole_grid_ = true;
    if (whole_grid_) {
        std::vector<int> all(grid_.size());
        for (std::size_t i = 0; i < all.size(); ++i) all[i] = static_cast<int>(i);
        sample_grid(all);
        first_not_positive(grid_);
    }
}

void SampledReference::sample_grid(std::span<const int> indices) const {
    const std::lock_guard lock(grid_mutex_);
    // Whole blocks of kGridBlock points: the neighbours of a point asked for come at no extra cost, for later calls.
    std::vector<int> missing;
    std::vector<double> mu;
    const int size = static_cast<int>(grid_.size());
    for (const int i : indices)
        if (!grid_sampled_[static_cast<std::size_t>(i)])
            for (int j = i - i % kGridBlock; j < std::min(i - i % kGridBlock + kGridBlock, size); ++j)
                if (!grid_sampled_[static_cast<std::size_t>(j)]) {
                    grid_sampled_[static_cast<std::size_t>(j)] = 1;  // once, even if listed twice
                    missing.push_back(j);
                    mu.push_back(grid_[static_cast<std::size_t>(j)].mu);
                }
    if (missing.empty()) return;
    const std::vector<RGB> values = curve_(std::span<const double>(mu));
    const std::vector<Lab> labs = lab(values);
    for (std::size_t j = 0; j < missing.size(); ++j) {
        Sample& s = grid_[static_cast<std::size_t>(missing[j])];
        s.value = values[j];
        s.lab = labs[j];
    }
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
