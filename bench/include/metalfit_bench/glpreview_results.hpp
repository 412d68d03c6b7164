// The GPU side of the benchmark comes from the preview executable `glpreview` (next to metalfit in <build>/bin):
//   glpreview --bench-shaders [--quick] --json       → ShaderBench   (full-screen pass per model at 1024²)
//   glpreview --bench-localization [--quick] --json  → LocalizationBench (rooms × modes × iterations)
// Parsing is strict: a missing key or a wrong type is an error naming the field.
#pragma once

#include <array>
#include <filesystem>
#include <optional>
#include <string>
#include <vector>

#include <nlohmann/json.hpp>

namespace metalfit::bench {

struct ShaderTiming {
    std::string model;  // a model id or "reference-lut"
    double ms_per_frame = 0;
    double ratio_to_conductor_rgb = 0;
    std::optional<double> ratio_noise;                     // half the interquartile range of the per-round ratios
    std::optional<std::array<double, 2>> ratio_quartiles;  // their first and third quartiles
};

struct ShaderBench {
    std::string renderer;
    int width = 0, height = 0;
    int frames = 0;
    int evaluations_per_pixel = 1;  // model evaluations per pixel of the pass (optional in the JSON)
    std::string clock;              // the clock of the frame timer ("process-cpu", "wall"; optional in the JSON)
    std::vector<ShaderTiming> models;
    const ShaderTiming* find(std::string_view model) const;
};

struct LocalizationRow {
    std::string mode;                     // "classic", "box-parallax", "distance-impostor"
    std::optional<std::string> strategy;  // null, "secant", "false-position", "mixed", "illinois", "safe-secant"
    int iterations = 0;                   // the limit
    int search_steps = 0;                 // the linear search before the refinement (illinois, safe-secant)
    std::optional<double> tolerance;      // the impostor's stop on |ρ − 1| (null outside it)
    double mean_iterations = 0;           // steps the sphere's pixels took, on average
    double ms_per_frame = 0;
    double ratio_to_classic = 0;
    double ratio_noise = 0;  // half the interquartile range of the per-round ratios
    double rmse = 0;
    double mean_abs = 0;
};

struct LocalizationRoom {
    std::string room;
    std::vector<LocalizationRow> rows;
};

struct LocalizationBench {
    std::string renderer;
    int width = 0, height = 0;
    std::vector<LocalizationRoom> rooms;
};

// Throw std::runtime_error("<field>: <what is wrong>").
ShaderBench parse_shader_bench(const nlohmann::json& j);
LocalizationBench parse_localization_bench(const nlohmann::json& j);

nlohmann::json to_json(const ShaderBench& b);
nlohmann::json to_json(const LocalizationBench& b);

// A GPU section: the parsed result, or why it was skipped (one line).
template <class T>
struct GpuSection {
    std::optional<T> value;
    std::string skipped;
};

// Runs `glpreview <mode> [--quick] --json` and parses its stdout. Never throws: a missing executable, a failure
// (non-zero exit: its last stderr line), unparsable output or a schema error become `skipped`.
GpuSection<ShaderBench> run_shader_bench(const std::filesystem::path& glpreview, bool quick);
GpuSection<LocalizationBench> run_localization_bench(const std::filesystem::path& glpreview, bool quick);

}  // namespace metalfit::bench
