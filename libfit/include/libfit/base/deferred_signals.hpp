// SIGINT, SIGTERM and SIGHUP held back while output files are written, so that an interrupted run can remove its
// temporaries before it ends by the signal it was sent (docs/cli.md, "Output files and interrupted runs").
#pragma once

#include <stdexcept>

namespace metalfit {

// Thrown by DeferredSignals::throw_if_pending() when a deferred signal arrived: the writer cleans up and lets it pass.
class Interrupted : public std::runtime_error {
public:
    Interrupted() : std::runtime_error("interrupted by a signal") {}
};

// While one (or several nested) of these live, SIGINT, SIGTERM and SIGHUP only record that they arrived (signals
// already ignored stay ignored). When the outermost one ends, the previous handlers come back and a recorded signal
// is raised again: the process then ends as it would have, after its writer removed what it had staged.
class DeferredSignals {
public:
    DeferredSignals();
    ~DeferredSignals();
    DeferredSignals(const DeferredSignals&) = delete;
    DeferredSignals& operator=(const DeferredSignals&) = delete;

    static bool pending() noexcept;
    static void throw_if_pending();
};

}  // namespace metalfit
