#include "progress.hpp"

#include <unistd.h>

#include <cstdio>
#include <string>

namespace metalfit::cli {

TerminalProgress::TerminalProgress(const char* label) : label_(label), terminal_(isatty(STDERR_FILENO) != 0) {}

TerminalProgress::~TerminalProgress() {
    if (shown_) std::fputs(("\r" + std::string(60, ' ') + "\r").c_str(), stderr);
}

BatchProgress TerminalProgress::callback() {
    if (!terminal_) return {};
    return [this](std::size_t finished, std::size_t total) {
        if (total < 2) return;
        shown_ = true;
        const std::string line =
            "\r" + std::string(label_) + ": " + std::to_string(finished) + "/" + std::to_string(total) + " materials";
        std::fputs(line.c_str(), stderr);
        std::fflush(stderr);
    };
}

}  // namespace metalfit::cli
