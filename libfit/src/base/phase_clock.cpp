#include "libfit/base/phase_clock.hpp"

#include <ctime>

namespace metalfit {
namespace {

double seconds_of(clockid_t clock) {
    timespec t{};
    clock_gettime(clock, &t);
    return double(t.tv_sec) + 1e-9 * double(t.tv_nsec);
}

}  // namespace

double thread_cpu_seconds() { return seconds_of(CLOCK_THREAD_CPUTIME_ID); }
double process_cpu_seconds() { return seconds_of(CLOCK_PROCESS_CPUTIME_ID); }

PhaseClock::PhaseClock() : cpu_(thread_cpu_seconds()), wall_(std::chrono::steady_clock::now()) {}

void PhaseClock::charge(PhaseTime& phase) {
    const double cpu = thread_cpu_seconds();
    const auto wall = std::chrono::steady_clock::now();
    phase.cpu += cpu - cpu_;
    phase.wall += std::chrono::duration<double>(wall - wall_).count();
    cpu_ = cpu;
    wall_ = wall;
}

}  // namespace metalfit
