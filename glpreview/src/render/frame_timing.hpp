// Timing GL work: milliseconds of a call followed by glFinish, and rounds of such calls through libfit's
// one interleaved timer (libfit/base/interleaved_timer.hpp; statistics: libfit/base/sample_statistics.hpp) on the
// clock that sees the work: on a software rasteriser (llvmpipe, softpipe, SwiftShader) the process's CPU time (its
// rasteriser threads included, not the time other processes had the cores), on a hardware GPU the wall clock; and the
// benchmarks' rounds (interleaved_rounds) on a hardware GPU through its timer queries (GL_TIME_ELAPSED).
#pragma once

#include <cstdlib>
#include <string>
#include <string_view>
#include <vector>

#include "glpreview/gl/gl.hpp"
#include "glpreview/gl/gl_context.hpp"
#include "libfit/base/errors.hpp"
#include "libfit/base/interleaved_timer.hpp"
#include "libfit/base/sample_statistics.hpp"

namespace metalfit::glpreview {

// The clock the frame timers read for a renderer (GL_RENDERER): the process's CPU time on a software rasteriser,
// the wall clock on a hardware GPU.
inline TimingClock clock_for_renderer(std::string_view renderer) {
    return is_software_renderer(renderer) ? TimingClock::process_cpu : TimingClock::wall;
}

// The clock for the current context's renderer.
inline TimingClock frame_clock() {
    const auto* name = reinterpret_cast<const char*>(glGetString(GL_RENDERER));
    return clock_for_renderer(name ? name : "");
}

// The timer of the benchmarks' rounds: on a hardware GPU its timer queries (GL_TIME_ELAPSED around each frame's
// commands: the GPU's own time for them, without the submission and the driver's waits the wall clock adds), on a
// software rasteriser the process's CPU time (whose timer queries would read a clock of the rasteriser's threads).
// GLPREVIEW_FRAME_TIMER=gpu-time-elapsed|process-cpu|wall chooses one (scripts/gpu-bench.sh; the tests use
// gpu-time-elapsed on llvmpipe, whose timer queries work); another value is an error naming the three.
enum class FrameTimer { process_cpu, wall, gpu_time_elapsed };

inline const char* frame_timer_name(FrameTimer timer) {
    switch (timer) {
        case FrameTimer::process_cpu: return "process-cpu";
        case FrameTimer::wall: return "wall";
        case FrameTimer::gpu_time_elapsed: return "gpu-time-elapsed";
    }
    return "?";
}

inline FrameTimer frame_timer() {
    if (const char* chosen = std::getenv("GLPREVIEW_FRAME_TIMER"); chosen != nullptr && *chosen != '\0') {
        for (const FrameTimer t : {FrameTimer::process_cpu, FrameTimer::wall, FrameTimer::gpu_time_elapsed})
            if (std::string_view(chosen) == frame_timer_name(t)) return t;
        throw UsageError(std::string("GLPREVIEW_FRAME_TIMER=") + chosen +
                         ": not a frame timer (gpu-time-elapsed, process-cpu or wall)");
    }
    return frame_clock() == TimingClock::process_cpu ? FrameTimer::process_cpu : FrameTimer::gpu_time_elapsed;
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

// The milliseconds of every round per variant on frame_timer(): `rounds` rounds, each timing every variant in turn,
// after one untimed call of each (its warm-up: compile, first-use costs). On a CPU clock through libfit's interleaved
// timer, one call (ended by glFinish) per sample; with GPU timer queries, the GPU time between a GL_TIME_ELAPSED query's
// begin and end around each call, its result waited for before the next. Medians and ratios are libfit's (median,
// paired_ratio), as on the CPU.
using RoundTimes = std::vector<std::vector<double>>;
template <typename Variant>
RoundTimes interleaved_rounds(const std::vector<Variant>& variants, int rounds) {
    if (frame_timer() == FrameTimer::gpu_time_elapsed) {
        GLuint query = 0;
        glCreateQueries(GL_TIME_ELAPSED, 1, &query);
        const auto gpu_ms = [query](const Variant& v) {
            glBeginQuery(GL_TIME_ELAPSED, query);
            v();
            glEndQuery(GL_TIME_ELAPSED);
            GLuint64 ns = 0;
            glGetQueryObjectui64v(query, GL_QUERY_RESULT, &ns);  // waits for the GPU
            return 1e-6 * static_cast<double>(ns);
        };
        for (const Variant& v : variants) gpu_ms(v);
        RoundTimes ms(variants.size());
        for (int r = 0; r < rounds; ++r)
            for (std::size_t i = 0; i < variants.size(); ++i) ms[i].push_back(gpu_ms(variants[i]));
        glDeleteQueries(1, &query);
        return ms;
    }
    std::vector<TimedJob> jobs;
    for (const Variant& v : variants)
        jobs.push_back({[&v] {
            v();
            glFinish();
        }});
    RoundTimes ms;
    const TimingClock clock = frame_timer() == FrameTimer::wall ? TimingClock::wall : TimingClock::process_cpu;
    for (const JobTiming& t : time_interleaved(jobs, {rounds, 0.0, clock})) {
        std::vector<double>& round_ms = ms.emplace_back();
        for (double ns : t.ns_per_item) round_ms.push_back(ns * 1e-6);
    }
    return ms;
}

}  // namespace metalfit::glpreview
