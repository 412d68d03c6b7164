#include "progress.hpp"

#include <unistd.h>

#include <cstdio>

namespace metalfit::cli {

TerminalProgress::TerminalProgress(const char* label) : label_(label), terminal_(isatty(STDERR_FILENO) != 0) {}

TerminalProgress::~TerminalProgress() {
    if (shown_) std::fprintf(stderr, "\r%*s\r", 60, "");
}

BatchProgress TerminalProgress::callback() {
    if (!terminal_) return {};
    return [this](std::size_t finished, std::size_t total) {
        if (total < 2) return;
        shown_ = true;
        std::fprintf(stderr, "\r%s: %zu/%zu materials", label_, finished, total);
        std::fflush(stderr);
    };
}

}  // namespace metalfit::cli
