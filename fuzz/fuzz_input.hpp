// Shared by the fuzz targets: the input as a file the loaders read, and what counts as a finding.
#pragma once

#include <unistd.h>

#include <cstdint>
#include <cstdlib>
#include <exception>
#include <filesystem>
#include <fstream>
#include <string>

#include "libfit/base/errors.hpp"

namespace metalfit::fuzz {

// A file holding the fuzz input, named `name` in a folder of this process (the loaders take paths).
inline std::filesystem::path input_file(const std::uint8_t* data, std::size_t size, const std::string& name) {
    static const std::filesystem::path dir = [] {
        const auto d = std::filesystem::temp_directory_path() / ("metalfit-fuzz-" + std::to_string(::getpid()));
        std::filesystem::create_directories(d);
        return d;
    }();
    const std::filesystem::path file = dir / name;
    std::ofstream(file, std::ios::binary | std::ios::trunc)
        .write(reinterpret_cast<const char*>(data), static_cast<std::streamsize>(size));
    return file;
}

// Bad input must be one of metalfit's documented errors; anything else (an "internal error", exit 1) is a finding,
// reported by aborting so that libFuzzer keeps the input.
template <class F>
void expect_only_documented_errors(F&& load) {
    try {
        load();
    } catch (const InputError&) {
    } catch (const UsageError&) {
    } catch (const ColorConfigError&) {
    } catch (const std::exception& e) {
        std::fprintf(stderr, "finding: internal error: %s\n", e.what());
        std::abort();
    }
}

}  // namespace metalfit::fuzz
