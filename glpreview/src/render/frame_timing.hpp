// Timing GL work: milliseconds of a call followed by glFinish, and rounds of such calls through libfit's
// one interleaved timer (libfit/base/interleaved_timer.hpp; statistics: libfit/base/sample_statistics.hpp) on the
// clock that sees the work: on a software rasteriser (llvmpipe, softpipe, SwiftShader) the process's CPU time (its
// rasteriser threads included, not the time other processes had the cores), on a hardware GPU the wall clock.
#pragma once

#include <string_view>
#include <vector>

#include "glpreview/gl/gl.hpp"
#include "libfit/base/interleaved_timer.hpp"
#include "libfit/base/sample_statistics.hpp"

namespace metalfit::glpreview {

// The clock the frame timers read for a renderer (GL_RENDERER): the process's CPU time on a software rasteriser,
// the wall clock on a hardware GPU.
inline TimingClock clock_for_renderer(std::string_view renderer) {
    for (const char* software : {"llvmpipe", "softpipe", "SwiftShader", "swrast"})
        if (renderer.find(software) != std::string_view::npos) return TimingClock::process_cpu;
    return TimingClock::wall;
}

// The clock for the current context's renderer.
inline TimingClock frame_clock() {
    const auto* name = reinterpret_cast<const char*>(glGetString(GL_RENDERER));
    return clock_for_renderer(name ? name : "");
}

// Milliseconds on frame_clock() from the call of `work` until the GL has finished everything it issued.
template <typename Work>
double finished_ms(Work&& work) {
    const TimingClock clock = frame_clock();
    const double start = clock_seconds(clock);
    work();
    glFinish();
    return 1e3 * (clock_seconds(clock) - start);
}

// The milliseconds of every round per variant: libfit's interleaved timer with one call (ended by glFinish) per
// sample on frame_clock(), `rounds` rounds, each timing every variant in turn; the timer's calibration call of each is its warm-up
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
    for (const JobTiming& t : time_interleaved(jobs, {rounds, 0.0, frame_clock()})) {
        std::vector<double>& round_ms = ms.emplace_back();
        for (double ns : t.ns_per_item) round_ms.push_back(ns * 1e-6);
    }
    return ms;
}

}  // namespace metalfit::glpreview
