// Where the time of a computation goes, phase by phase: CPU time from the calling thread's own CPU clock
// (CLOCK_THREAD_CPUTIME_ID: what the thread computed, not what it waited while other threads or processes ran) and
// wall time (steady clock) kept separately, so that a loaded machine shows up as wall > CPU instead of inflating the
// phases' share of the work.
#pragma once

#include <chrono>

namespace metalfit {

struct PhaseTime {
    double cpu = 0;   // seconds of this thread's CPU
    double wall = 0;  // seconds of wall-clock time
    PhaseTime& operator+=(const PhaseTime& o) {
        cpu += o.cpu;
        wall += o.wall;
        return *this;
    }
};

// CPU seconds used so far by the calling thread, and by the whole process (every thread).
double thread_cpu_seconds();
double process_cpu_seconds();

// Adds the CPU and wall time since the last charge (or construction) to a phase. One clock per thread.
class PhaseClock {
public:
    PhaseClock();
    void charge(PhaseTime& phase);

private:
    double cpu_;
    std::chrono::steady_clock::time_point wall_;
};

}  // namespace metalfit
