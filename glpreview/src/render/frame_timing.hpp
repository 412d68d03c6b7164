// Timing GL work: wall-clock milliseconds of a call followed by glFinish, and rounds of such calls through libfit's
// one interleaved timer (libfit/base/interleaved_timer.hpp; statistics: libfit/base/sample_statistics.hpp).
#pragma once

#include <chrono>
#include <vector>

#include "glpreview/gl/gl.hpp"
#include "libfit/base/interleaved_timer.hpp"
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

// The milliseconds of every round per variant: libfit's interleaved timer with one call (ended by glFinish) per
// sample, `rounds` rounds, each timing every variant in turn; the timer's calibration call of each is its warm-up
// (compile, first-use costs). Medians and ratios are libfit's (median, paired_ratio), as on the CPU.
using RoundTimes = std::vector<std::vector<double>>;
template <typename Variant>
RoundTimes interleaved_rounds(const std::vector<Variant>& variants, int rounds) {
    std::vector<TimedJob> jobs;
    for (const Variant& v : variants)
        jobs.push_back({[&v] {
            v();
            glFinish();
        }});
    RoundTimes ms;
    for (const JobTiming& t : time_interleaved(jobs, {rounds, 0.0})) {
        std::vector<double>& round_ms = ms.emplace_back();
        for (double ns : t.ns_per_item) round_ms.push_back(ns * 1e-6);
    }
    return ms;
}

}  // namespace metalfit::glpreview
