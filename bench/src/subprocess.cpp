#include "metalfit_bench/subprocess.hpp"

#include <sys/wait.h>
#include <unistd.h>

#include <array>
#include <cstdio>
#include <cstdlib>
#include <fstream>
#include <random>
#include <sstream>

namespace metalfit::bench {
namespace {

std::string quoted(const std::string& s) {
    std::string q = "'";
    for (char c : s) q += c == '\'' ? std::string("'\\''") : std::string(1, c);
    return q + "'";
}

}  // namespace

std::optional<std::filesystem::path> find_on_path(const std::string& name) {
    const char* path = std::getenv("PATH");
    if (!path) return std::nullopt;
    std::stringstream dirs(path);
    for (std::string dir; std::getline(dirs, dir, ':');) {
        if (dir.empty()) continue;
        const std::filesystem::path candidate = std::filesystem::path(dir) / name;
        if (access(candidate.c_str(), X_OK) == 0 && std::filesystem::is_regular_file(candidate)) return candidate;
    }
    return std::nullopt;
}

std::filesystem::path executable_dir() {
    std::error_code ec;
    const std::filesystem::path exe = std::filesystem::read_symlink("/proc/self/exe", ec);
    return ec ? std::filesystem::path() : exe.parent_path();
}

ProcessResult run_process(const std::filesystem::path& program, const std::vector<std::string>& arguments) {
    ProcessResult result;
    std::random_device random;
    const std::filesystem::path err_file =
        std::filesystem::temp_directory_path() /
        ("metalfit-bench-" + std::to_string(getpid()) + "-" + std::to_string(random()) + ".err");
    std::string command = quoted(program.string());
    for (const std::string& a : arguments) command += " " + quoted(a);
    command += " 2>" + quoted(err_file.string());
    FILE* pipe = popen(command.c_str(), "r");
    if (!pipe) return result;
    std::array<char, 4096> buffer{};
    for (std::size_t n; (n = std::fread(buffer.data(), 1, buffer.size(), pipe)) > 0;)
        result.out.append(buffer.data(), n);
    const int status = pclose(pipe);
    result.exit_code = WIFEXITED(status) ? WEXITSTATUS(status) : -1;
    {
        std::ifstream err(err_file);
        std::stringstream text;
        text << err.rdbuf();
        result.err = text.str();
    }
    std::error_code ec;
    std::filesystem::remove(err_file, ec);
    return result;
}

std::string last_line(const std::string& text) {
    std::stringstream lines(text);
    std::string last;
    for (std::string line; std::getline(lines, line);)
        if (line.find_first_not_of(" \t\r") != std::string::npos) last = line;
    return last;
}

}  // namespace metalfit::bench
