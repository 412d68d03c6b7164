// The timer of `metalfit bench`: every job is timed in turn, round after round (interleaved), so that a change of
// load on a shared machine hits all jobs alike; a job's time is the median over rounds, and a ratio between two jobs
// is the median of the per-round ratios, with its spread (noise) as the half interquartile range.
#pragma once

#include <functional>
#include <string>
#include <vector>

namespace metalfit::bench {

struct TimedJob {
    std::function<void()> run;  // one call does `items` units of work
    double items = 1;
};

struct TimingOptions {
    int rounds = 15;                    // samples per job
    double seconds_per_sample = 0.01;   // each sample repeats the job until about this long
};

struct JobTiming {
    std::vector<double> ns_per_item;  // one per round
    double median_ns = 0;
};

// Calibrates the repetitions of each job, then runs the rounds. Never asserts anything about the times.
std::vector<JobTiming> time_interleaved(const std::vector<TimedJob>& jobs, const TimingOptions& options);

struct Ratio {
    double median = 0;  // median over rounds of a[r] / b[r]
    double noise = 0;   // half the interquartile range of the same ratios
};
Ratio ratio(const JobTiming& a, const JobTiming& b);

double median(std::vector<double> values);            // average of the middle two for an even count; NaN if empty
double quantile(std::vector<double> values, double q);  // linear interpolation between order statistics

}  // namespace metalfit::bench
