#include "libfit/base/interleaved_timer.hpp"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <ctime>

namespace metalfit {
namespace {

double seconds_of(const TimedJob& job, long repetitions, TimingClock clock) {
    const double start = clock_seconds(clock);
    for (long i = 0; i < repetitions; ++i) job.run();
    return clock_seconds(clock) - start;
}

}  // namespace

double clock_seconds(TimingClock clock) {
    if (clock == TimingClock::wall)
        return std::chrono::duration<double>(std::chrono::steady_clock::now().time_since_epoch()).count();
    timespec t{};
    clock_gettime(clock == TimingClock::thread_cpu ? CLOCK_THREAD_CPUTIME_ID : CLOCK_PROCESS_CPUTIME_ID, &t);
    return double(t.tv_sec) + 1e-9 * double(t.tv_nsec);
}

const char* clock_name(TimingClock clock) {
    switch (clock) {
        case TimingClock::thread_cpu: return "thread-cpu";
        case TimingClock::process_cpu: return "process-cpu";
        case TimingClock::wall: return "wall";
    }
    return "?";
}

std::vector<JobTiming> time_interleaved(const std::vector<TimedJob>& jobs, const TimingOptions& options) {
    // Calibration: double the repetitions until one sample takes a tenth of the target, then scale (warms caches too).
    std::vector<long> repetitions(jobs.size(), 1);
    for (std::size_t j = 0; j < jobs.size(); ++j) {
        double s = seconds_of(jobs[j], repetitions[j], options.clock);
        while (s < options.seconds_per_sample / 10 && repetitions[j] < (1L << 40)) {
            repetitions[j] *= 2;
            s = seconds_of(jobs[j], repetitions[j], options.clock);
        }
        repetitions[j] = std::max(1L, std::lround(repetitions[j] * options.seconds_per_sample / std::max(s, 1e-9)));
    }
    std::vector<JobTiming> timings(jobs.size());
    for (int r = 0; r < options.rounds; ++r)
        for (std::size_t j = 0; j < jobs.size(); ++j) {
            const double s = seconds_of(jobs[j], repetitions[j], options.clock);
            timings[j].ns_per_item.push_back(1e9 * s / (static_cast<double>(repetitions[j]) * jobs[j].items));
        }
    for (JobTiming& t : timings) t.median_ns = median(t.ns_per_item);
    return timings;
}

Ratio ratio(const JobTiming& a, const JobTiming& b) { return paired_ratio(a.ns_per_item, b.ns_per_item); }

}  // namespace metalfit
