// PhaseClock: CPU time from the thread's own clock, wall time apart (a sleeping thread uses wall, not CPU).
#include <gtest/gtest.h>

#include <chrono>
#include <cmath>
#include <thread>

#include "libfit/base/phase_clock.hpp"

namespace metalfit {
namespace test_phase_clock {

TEST(PhaseClock, SleepingIsWallTimeNotCpuTime) {
    PhaseClock clock;
    PhaseTime sleeping, working;
    std::this_thread::sleep_for(std::chrono::milliseconds(60));
    clock.charge(sleeping);
    volatile double x = 0;
    const double until = thread_cpu_seconds() + 0.02;
    while (thread_cpu_seconds() < until) x = x + std::sqrt(x + 1.0);
    clock.charge(working);
    EXPECT_GE(sleeping.wall, 0.06);
    EXPECT_LT(sleeping.cpu, 0.03) << "a sleep was charged as CPU time";
    EXPECT_GE(working.cpu, 0.02);
    EXPECT_GE(working.wall, working.cpu * 0.99) << "one thread cannot compute longer than it ran";
    EXPECT_LE(thread_cpu_seconds(), process_cpu_seconds() + 1e-3);
}

TEST(PhaseClock, PhasesAdd) {
    PhaseTime a{1.0, 2.0};
    a += PhaseTime{0.5, 0.25};
    EXPECT_EQ(a.cpu, 1.5);
    EXPECT_EQ(a.wall, 2.25);
}

}  // namespace test_phase_clock
}  // namespace metalfit
