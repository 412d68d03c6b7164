// Helpers shared by the test files: fixture paths, message matchers, temporary folders.
#pragma once

#include <gtest/gtest.h>
#include <sys/wait.h>
#include <unistd.h>

#include <cmath>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <stdexcept>
#include <string>

#include <nlohmann/json.hpp>

#include "libfit/spectral/complex_index.hpp"
#include "test_paths.hpp"

namespace metalfit::test {

namespace fs = std::filesystem;

inline const fs::path kFixtures{kFixturesDir};
inline const fs::path kData{kDataDir};

inline ::testing::AssertionResult Contains(const std::string& haystack, const std::string& needle) {
    if (haystack.find(needle) != std::string::npos) return ::testing::AssertionSuccess();
    return ::testing::AssertionFailure() << "'" << haystack << "' does not contain '" << needle << "'";
}

inline ::testing::AssertionResult StartsWith(const std::string& s, const std::string& prefix) {
    if (s.rfind(prefix, 0) == 0) return ::testing::AssertionSuccess();
    return ::testing::AssertionFailure() << "'" << s << "' does not start with '" << prefix << "'";
}

// The number of materials of the built-in database, counted from data/catalog.json itself (not through Catalog),
// so that a test says "every material" without a literal count.
inline std::size_t catalog_material_count() {
    std::ifstream in(kData / "catalog.json");
    return nlohmann::json::parse(in).at("materials").size();
}

inline std::string read_file(const fs::path& p) {
    std::ifstream in(p, std::ios::binary);
    return {std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>()};
}

// What a command printed and how it ended (exit code −1 when it did not exit normally).
struct CommandResult {
    int exit_code;
    std::string out, err;
};

// Runs `executable` with `args` (already shell-quoted) under the environment prefix `env` ("OCIO=": metalfit's own
// colour config) with no standard input; stdout and stderr pass through files in `scratch`, removed afterwards.
inline CommandResult run_command(const fs::path& executable, const std::string& args, const fs::path& scratch,
                                 const std::string& env = "OCIO=") {
    const fs::path out = scratch / "stdout.txt", err = scratch / "stderr.txt";
    const std::string command = "env " + env + " '" + executable.string() + "' " + args + " >'" + out.string() +
                                "' 2>'" + err.string() + "' </dev/null";
    const int status = std::system(command.c_str());
    CommandResult result{WIFEXITED(status) ? WEXITSTATUS(status) : -1, read_file(out), read_file(err)};
    fs::remove(out);
    fs::remove(err);
    return result;
}

// The pid of a process that has ended (a child that exits at once, reaped): for staging names a killed writer left
// (".<name>.metalfit-staging.<pid>.<16 hex>", libfit/src/base/exclusive_file.hpp).
inline pid_t dead_pid() {
    const pid_t pid = ::fork();
    if (pid == 0) ::_exit(0);
    int status = 0;
    ::waitpid(pid, &status, 0);
    return pid;
}

// A staging name a killed writer of `target` (a file name) left: `mark` is "staging" (folders) or "tmp" (files).
inline std::string stale_staging_name(const std::string& target, const std::string& mark = "staging") {
    return "." + target + ".metalfit-" + mark + "." + std::to_string(dead_pid()) + ".0123456789abcdef";
}

// A fresh folder per test (named after it and the process), removed with everything in it.
class TempDir {
public:
    TempDir() {
        const auto* info = ::testing::UnitTest::GetInstance()->current_test_info();
        path_ = fs::temp_directory_path() / ("metalfit-test-" + std::string(info->test_suite_name()) + "-" +
                                             info->name() + "-" + std::to_string(::getpid()));
        fs::remove_all(path_);
        fs::create_directories(path_);
    }
    ~TempDir() {
        std::error_code ec;
        fs::permissions(path_, fs::perms::owner_all, fs::perm_options::add, ec);  // a test may make it read-only
        fs::remove_all(path_, ec);
    }
    TempDir(const TempDir&) = delete;
    TempDir& operator=(const TempDir&) = delete;

    const fs::path& path() const { return path_; }
    fs::path write(const std::string& name, const std::string& contents) const {
        const fs::path p = path_ / name;
        std::ofstream(p, std::ios::binary) << contents;
        return p;
    }

private:
    fs::path path_;
};

// The tabulated spectrum behind a curve (throws when it is a formula or a constant).
inline const Spectrum& tabulated(const SpectralCurve& c) {
    const Spectrum* s = c.tabulated();
    if (s == nullptr) throw std::runtime_error("curve is " + c.kind() + ", not tabulated");
    return *s;
}

// Index of the sample at `nm` (to 1e-9 nm), or size() if there is none.
inline std::size_t index_of(const Spectrum& s, double nm) {
    for (std::size_t i = 0; i < s.size(); ++i)
        if (std::abs(s.wavelengths()[i] - nm) < 1e-9) return i;
    return s.size();
}

}  // namespace metalfit::test
