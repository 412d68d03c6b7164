// Progress of a batch fit on the terminal: "metalfit fit: 12/29 materials" on stderr while it is a terminal, the
// line cleared when the batch ends.
#pragma once

#include <cstddef>

#include "libfit/fit/fit_batch.hpp"

namespace metalfit::cli {

class TerminalProgress {
public:
    TerminalProgress();
    ~TerminalProgress();  // clears the line
    TerminalProgress(const TerminalProgress&) = delete;
    TerminalProgress& operator=(const TerminalProgress&) = delete;

    // What fit_materials calls; empty when stderr is no terminal.
    BatchProgress callback();

private:
    bool shown_ = false;
    bool terminal_ = false;
};

}  // namespace metalfit::cli
