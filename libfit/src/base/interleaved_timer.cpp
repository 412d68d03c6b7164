#include "libfit/base/interleaved_timer.hpp"

#include <algorithm>
#include <chrono>
#include <cmath>

namespace metalfit {
namespace {

using Clock = std::chrono::steady_clock;

double seconds_of(const TimedJob& job, long repetitions) {
    const auto start = Clock::now();
    for (long i = 0; i < repetitions; ++i) job.run();
    return std::chrono::duration<double>(Clock::now() - start).count();
}

}  // namespace

std::vector<JobTiming> time_interleaved(const std::vector<TimedJob>& jobs, const TimingOptions& options) {
    // Calibration: double the repetitions until one sample takes a tenth of the target, then scale (warms caches too).
    std::vector<long> repetitions(jobs.size(), 1);
    for (std::size_t j = 0; j < jobs.size(); ++j) {
        double s = seconds_of(jobs[j], repetitions[j]);
        while (s < options.seconds_per_sample / 10 && repetitions[j] < (1L << 40)) {
            repetitions[j] *= 2;
            s = seconds_of(jobs[j], repetitions[j]);
        }
        repetitions[j] = std::max(1L, std::lround(repetitions[j] * options.seconds_per_sample / std::max(s, 1e-9)));
    }
    std::vector<JobTiming> timings(jobs.size());
    for (int r = 0; r < options.rounds; ++r)
        for (std::size_t j = 0; j < jobs.size(); ++j) {
            const double s = seconds_of(jobs[j], repetitions[j]);
            timings[j].ns_per_item.push_back(1e9 * s / (static_cast<double>(repetitions[j]) * jobs[j].items));
        }
    for (JobTiming& t : timings) t.median_ns = median(t.ns_per_item);
    return timings;
}

Ratio ratio(const JobTiming& a, const JobTiming& b) { return paired_ratio(a.ns_per_item, b.ns_per_item); }

}  // namespace metalfit
