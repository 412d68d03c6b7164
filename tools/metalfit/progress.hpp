// Progress of a batch on the terminal: "metalfit fit: 12/29 materials" (or the label given: "metalfit report: renders
// 3/41 materials") on stderr while it is a terminal, nothing when it is not; the line cleared when the batch ends.
#pragma once

#include <cstddef>

#include "libfit/fit/fit_batch.hpp"

namespace metalfit::cli {

class TerminalProgress {
public:
    explicit TerminalProgress(const char* label = "metalfit fit");
    ~TerminalProgress();  // clears the line
    TerminalProgress(const TerminalProgress&) = delete;
    TerminalProgress& operator=(const TerminalProgress&) = delete;

    // What fit_materials (or the report's renders) call; empty when stderr is no terminal.
    BatchProgress callback();

private:
    const char* label_;
    bool shown_ = false;
    bool terminal_ = false;
};

}  // namespace metalfit::cli
