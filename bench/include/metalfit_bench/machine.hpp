// The machine a benchmark ran on, for the top of the report: CPU model, cores, compiler, build type.
#pragma once

#include <string>

#include <nlohmann/json.hpp>

namespace metalfit::bench {

struct Machine {
    std::string cpu;         // /proc/cpuinfo "model name" ("unknown CPU" elsewhere)
    unsigned cores = 0;      // std::thread::hardware_concurrency()
    std::string os;          // uname: sysname release machine
    std::string compiler;    // CMake's compiler id and version
    std::string build_type;  // CMAKE_BUILD_TYPE of this build
    std::string flags;       // the build type's compiler flags

    static Machine describe();
    std::string one_line() const;
};

nlohmann::json to_json(const Machine& m);

}  // namespace metalfit::bench
