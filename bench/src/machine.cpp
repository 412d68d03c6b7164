#include "metalfit_bench/machine.hpp"

#include <sys/utsname.h>

#include <fstream>
#include <thread>

namespace metalfit::bench {
namespace {

std::string trim(std::string s) {
    const auto first = s.find_first_not_of(" \t");
    const auto last = s.find_last_not_of(" \t\r\n");
    return first == std::string::npos ? "" : s.substr(first, last - first + 1);
}

std::string cpu_model() {
    std::ifstream in("/proc/cpuinfo");
    for (std::string line; std::getline(in, line);)
        if (line.rfind("model name", 0) == 0) {
            const auto colon = line.find(':');
            if (colon != std::string::npos) return trim(line.substr(colon + 1));
        }
    return "unknown CPU";
}

}  // namespace

Machine Machine::describe() {
    Machine m;
    m.cpu = cpu_model();
    m.cores = std::thread::hardware_concurrency();
    utsname u{};
    if (uname(&u) == 0) m.os = std::string(u.sysname) + " " + u.release + " " + u.machine;
    m.compiler = METALFIT_CXX_COMPILER;
    m.build_type = METALFIT_BUILD_TYPE;
    m.flags = trim(METALFIT_CXX_FLAGS);
    return m;
}

std::string Machine::one_line() const {
    return cpu + ", " + std::to_string(cores) + " cores, " + os + "; " + compiler + ", " +
           (build_type.empty() ? std::string("no build type") : build_type + " build") +
           (flags.empty() ? "" : " (" + flags + ")");
}

nlohmann::json to_json(const Machine& m) {
    return {{"cpu", m.cpu},           {"cores", m.cores},           {"os", m.os},
            {"compiler", m.compiler}, {"build_type", m.build_type}, {"flags", m.flags}};
}

}  // namespace metalfit::bench
