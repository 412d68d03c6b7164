// Timing GL work: wall-clock milliseconds of a call followed by glFinish (statistics: libfit/base/sample_statistics.hpp).
#pragma once

#include <chrono>
#include <vector>

#include "glpreview/gl/gl.hpp"
#include "libfit/base/sample_statistics.hpp"

namespace metalfit::glpreview {

// Milliseconds from the call of `work` until the GL has finished everything it issued.
template <typename Work>
double finished_ms(Work&& work) {
    const auto start = std::chrono::steady_clock::now();
    work();
    glFinish();
    return std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - start).count();
}

// The milliseconds of every round per variant: `rounds` rounds, each timing one call of every variant in turn
// (between glFinish calls), after one warm-up call of each (compile, first-use costs). Medians and ratios are
// libfit's (median, paired_ratio), as on the CPU.
using RoundTimes = std::vector<std::vector<double>>;
template <typename Variant>
RoundTimes interleaved_rounds(const std::vector<Variant>& variants, int rounds) {
    RoundTimes ms(variants.size());
    for (const auto& v : variants) v();
    glFinish();
    for (int round = 0; round < rounds; ++round)
        for (std::size_t i = 0; i < variants.size(); ++i) ms[i].push_back(finished_ms(variants[i]));
    return ms;
}

}  // namespace metalfit::glpreview
