// The other way to be exact and cheap: a 1D table of the exact reference curve R_c(μ) at `entries` uniform μ in
// [0, 1] (μ_i = i / (entries − 1)), stored in float RGB, read with linear interpolation (what a 1D texture with
// linear filtering does, without the half-texel offset).
#pragma once

#include <array>
#include <vector>

#include "libfit/fit/metrics.hpp"
#include "libfit/reference/reference_curve.hpp"
#include "libfit/reference/sampled_reference.hpp"

namespace metalfit::bench {

class ReferenceLut {
public:
    // Samples the curve at `entries` μ (≥ 2).
    ReferenceLut(const ReferenceCurve& curve, int entries);

    int entries() const { return entries_; }

    // RGB at μ (clamped to [0, 1]), linear interpolation between the two nearest entries.
    std::array<float, 3> operator()(float mu) const {
        const float x = (mu < 0.0f ? 0.0f : mu > 1.0f ? 1.0f : mu) * static_cast<float>(entries_ - 1);
        int i = static_cast<int>(x);
        if (i > entries_ - 2) i = entries_ - 2;
        const float f = x - static_cast<float>(i);
        const float* a = &rgb_[3 * static_cast<std::size_t>(i)];
        return {a[0] + f * (a[3] - a[0]), a[1] + f * (a[4] - a[1]), a[2] + f * (a[5] - a[2])};
    }

    // rel_rms per channel of the table against the reference at its quadrature nodes (docs/fitting.md, "Definitions").
    PerChannel rel_rms(const SampledReference& reference) const;

private:
    int entries_;
    std::vector<float> rgb_;  // 3 × entries, interleaved
};

}  // namespace metalfit::bench
