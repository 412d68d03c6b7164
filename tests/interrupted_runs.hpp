// What the kill tests of the writers share (test_export_interrupted.cpp, test_writers_interrupted.cpp): a real
// executable started so that it can be signalled, signalled at a point of its run (or reaped if it ended first), and a
// folder read back as its files and as its names.
#pragma once

#include <fcntl.h>
#include <signal.h>
#include <spawn.h>
#include <sys/types.h>
#include <sys/wait.h>

#include <algorithm>
#include <cerrno>
#include <chrono>
#include <filesystem>
#include <map>
#include <stdexcept>
#include <string>
#include <string_view>
#include <thread>
#include <vector>

#include "test_support.hpp"

extern char** environ;

namespace metalfit::test {

// `exe args` with $OCIO unset (metalfit's own config) and stdin, stdout and stderr on /dev/null; the caller waits for
// it (waitpid).
inline pid_t spawn_quietly(const std::string& exe, const std::vector<std::string>& args) {
    std::vector<std::string> all{exe};
    all.insert(all.end(), args.begin(), args.end());
    std::vector<char*> argv;
    for (std::string& a : all) argv.push_back(a.data());
    argv.push_back(nullptr);
    std::vector<std::string> env_strings;
    for (char** e = environ; *e; ++e)
        if (!std::string_view(*e).starts_with("OCIO=")) env_strings.emplace_back(*e);
    std::vector<char*> env;
    for (std::string& e : env_strings) env.push_back(e.data());
    env.push_back(nullptr);
    posix_spawn_file_actions_t actions;
    posix_spawn_file_actions_init(&actions);
    posix_spawn_file_actions_addopen(&actions, 0, "/dev/null", O_RDONLY, 0);
    posix_spawn_file_actions_addopen(&actions, 1, "/dev/null", O_WRONLY, 0);
    posix_spawn_file_actions_addopen(&actions, 2, "/dev/null", O_WRONLY, 0);
    pid_t pid = -1;
    const int rc = posix_spawn(&pid, exe.c_str(), &actions, nullptr, argv.data(), env.data());
    posix_spawn_file_actions_destroy(&actions);
    if (rc != 0) throw std::runtime_error("posix_spawn failed");
    return pid;
}

// Sends `signal` to the child `pid` `seconds` from now unless it has ended by then, and reaps it; returns its wait
// status. The child is polled every millisecond instead of slept on for the whole `seconds`: a kill aimed past the end
// of a run (the kill tests aim up to 10 % past the length of a first run, and a run can be faster than that) costs no
// more than the run itself.
inline int kill_at(pid_t pid, double seconds, int signal) {
    using clock = std::chrono::steady_clock;
    const auto deadline =
        clock::now() + std::chrono::duration_cast<clock::duration>(std::chrono::duration<double>(seconds));
    int status = 0;
    for (;;) {
        const pid_t ended = ::waitpid(pid, &status, WNOHANG);
        if (ended == pid) return status;  // it finished before the signal
        if (ended < 0 && errno != EINTR) throw std::runtime_error("waitpid failed");
        const auto now = clock::now();
        if (now >= deadline) break;
        std::this_thread::sleep_for(std::min<clock::duration>(deadline - now, std::chrono::milliseconds(1)));
    }
    ::kill(pid, signal);
    while (::waitpid(pid, &status, 0) < 0 && errno == EINTR) {}
    return status;
}

// The regular files below `dir` (relative path → contents); empty when there is no such folder.
using Tree = std::map<std::string, std::string>;
inline Tree tree(const std::filesystem::path& dir) {
    Tree files;
    std::error_code ec;
    if (!std::filesystem::is_directory(dir, ec)) return files;
    for (const auto& e : std::filesystem::recursive_directory_iterator(dir))
        if (e.is_regular_file()) files[e.path().lexically_relative(dir).string()] = read_file(e.path());
    return files;
}

// The names in `dir`, sorted.
inline std::vector<std::string> names_in(const std::filesystem::path& dir) {
    std::vector<std::string> names;
    for (const auto& e : std::filesystem::directory_iterator(dir)) names.push_back(e.path().filename().string());
    std::sort(names.begin(), names.end());
    return names;
}

}  // namespace metalfit::test
