// Running the external tools the benchmarks use (glslangValidator, glpreview): find them, run them, capture stdout.
#pragma once

#include <filesystem>
#include <optional>
#include <string>
#include <vector>

namespace metalfit::bench {

// The first executable `name` on $PATH, if any.
std::optional<std::filesystem::path> find_on_path(const std::string& name);

// The folder of the running executable (/proc/self/exe), empty if unknown.
std::filesystem::path executable_dir();

struct ProcessResult {
    int exit_code = -1;  // -1: did not run or was killed by a signal
    std::string out;     // stdout
    std::string err;     // stderr
};

// Runs program with arguments (no shell interpretation of their contents: each is single-quoted), waiting for it.
ProcessResult run_process(const std::filesystem::path& program, const std::vector<std::string>& arguments);

// The last non-empty line of a text ("" if none), for one-line reasons.
std::string last_line(const std::string& text);

}  // namespace metalfit::bench
