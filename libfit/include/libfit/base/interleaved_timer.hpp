// The one timer of metalfit's measurements (`metalfit bench`'s CPU kernels and glpreview's GPU frames): every job
// is timed in turn, round after round (interleaved), so that a change of load on a shared machine hits all jobs alike; a job's time is the median over rounds, and a ratio between two jobs
// is the median of the per-round ratios, with its spread (noise) as the half interquartile range.
#pragma once

#include <functional>
#include <string>
#include <vector>

#include "libfit/base/sample_statistics.hpp"

namespace metalfit {

struct TimedJob {
    std::function<void()> run;  // one call does `items` units of work
    double items = 1;
};

struct TimingOptions {
    int rounds = 15;                   // samples per job
    double seconds_per_sample = 0.01;  // each sample repeats the job until about this long (0: one call per sample)
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
