#include "metalfit_bench/reference_lut.hpp"

#include <cmath>
#include <stdexcept>

namespace metalfit::bench {

ReferenceLut::ReferenceLut(const ReferenceCurve& curve, int entries) : entries_(entries) {
    if (entries < 2) throw std::invalid_argument("a reference LUT needs at least 2 entries");
    rgb_.reserve(3 * static_cast<std::size_t>(entries));
    for (int i = 0; i < entries; ++i) {
        const RGB v = curve(static_cast<double>(i) / (entries - 1));
        for (int c = 0; c < 3; ++c) rgb_.push_back(static_cast<float>(v[c]));
    }
}

PerChannel ReferenceLut::rel_rms(const SampledReference& reference) const {
    PerChannel sum{};
    for (const SampledReference::Sample& s : reference.nodes()) {
        const std::array<float, 3> v = (*this)(static_cast<float>(s.mu));
        for (int c = 0; c < 3; ++c) {
            const double e = (v[c] - s.value[c]) / s.value[c];
            sum[c] += s.weight * e * e;
        }
    }
    for (double& v : sum) v = std::sqrt(v);
    return sum;
}

}  // namespace metalfit::bench
