#include "libfit/base/deferred_signals.hpp"

#include <signal.h>

#include <array>
#include <mutex>

namespace metalfit {
namespace {

constexpr std::array<int, 3> kSignals{SIGINT, SIGTERM, SIGHUP};

volatile sig_atomic_t g_pending = 0;
int g_depth = 0;  // nesting of DeferredSignals (and writers on several threads), under g_mutex
std::mutex g_mutex;
std::array<struct sigaction, kSignals.size()> g_previous{};

extern "C" void record_signal(int signal) {
    if (g_pending == 0) g_pending = signal;
}

}  // namespace

DeferredSignals::DeferredSignals() {
    const std::lock_guard lock(g_mutex);
    if (g_depth++ > 0) return;
    g_pending = 0;
    for (std::size_t i = 0; i < kSignals.size(); ++i) {
        ::sigaction(kSignals[i], nullptr, &g_previous[i]);
        if (g_previous[i].sa_handler == SIG_IGN) continue;  // nohup and friends: keep ignoring
        struct sigaction action {};
        action.sa_handler = record_signal;
        ::sigemptyset(&action.sa_mask);
        action.sa_flags = SA_RESTART;
        ::sigaction(kSignals[i], &action, nullptr);
    }
}

DeferredSignals::~DeferredSignals() {
    std::unique_lock lock(g_mutex);
    if (--g_depth > 0) return;
    for (std::size_t i = 0; i < kSignals.size(); ++i) ::sigaction(kSignals[i], &g_previous[i], nullptr);
    if (const int signal = g_pending; signal != 0) {
        g_pending = 0;
        lock.unlock();
        ::raise(signal);
    }
}

bool DeferredSignals::pending() noexcept { return g_pending != 0; }

void DeferredSignals::throw_if_pending() {
    if (pending()) throw Interrupted();
}

}  // namespace metalfit
