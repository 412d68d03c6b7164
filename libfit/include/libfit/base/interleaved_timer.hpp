// The one timer of metalfit's measurements (`metalfit bench`'s CPU kernels and glpreview's GPU frames): every job
// is timed in turn, round after round (interleaved), so that a change of load on a shared machine hits all jobs
// alike; a job's time is the median over rounds, and a ratio between two jobs is the median of the per-round ratios,
// with its spread (noise) as the half interquartile range. Samples are read on a CPU-time clock by default (the
// thread's own: what it computed, not the time other processes had the core), so that the load of a shared machine
// does not stretch them; the wall clock only where the work runs elsewhere (a hardware GPU).
#pragma once

#include <functional>
#include <string>
#include <vector>

#include "libfit/base/sample_statistics.hpp"

namespace metalfit {

// The clock a sample is read on.
enum class TimingClock {
    thread_cpu,   // CLOCK_THREAD_CPUTIME_ID: work done on the calling thread (CPU kernels; llvmpipe without threads)
    process_cpu,  // CLOCK_PROCESS_CPUTIME_ID: every thread of the process (a software GPU's rasteriser threads)
    wall,         // steady_clock: elapsed time (a hardware GPU, whose work no CPU clock sees)
};
const char* clock_name(TimingClock clock);  // "thread-cpu", "process-cpu", "wall"
double clock_seconds(TimingClock clock);    // the clock's reading in seconds (differences only are meaningful)

struct TimedJob {
    std::function<void()> run;  // one call does `items` units of work
    double items = 1;
};

struct TimingOptions {
    int rounds = 15;                   // samples per job
    double seconds_per_sample = 0.01;  // each sample repeats the job until about this long (0: one call per sample)
    TimingClock clock = TimingClock::thread_cpu;
};

struct JobTiming {
    std::vector<double> ns_per_item;  // one per round
    double median_ns = 0;
};

// Calibrates the repetitions of each job (its first, untimed-for-the-result call is also its warm-up), then runs the
// rounds. Never asserts anything about the times.
std::vector<JobTiming> time_interleaved(const std::vector<TimedJob>& jobs, const TimingOptions& options);

// The ratio of two jobs timed in the same rounds (sample_statistics.hpp).
Ratio ratio(const JobTiming& a, const JobTiming& b);

}  // namespace metalfit
