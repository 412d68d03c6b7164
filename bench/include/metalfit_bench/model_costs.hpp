// The measured cost table (`metalfit bench --model-costs`, scripts/measure-model-costs.sh → data/model-costs.json,
// libfit's built-in cost table): per model, the shader's cost on the software GPU (glpreview's full-screen pass on
// llvmpipe) and the C++ definition's array loop on the CPU, both as ratios to conductor-rgb timed in interleaved
// rounds on a CPU-time clock with their noise, next to the SPIR-V instruction count and its class-weighted form, and
// the rank correlations (Spearman) between the counts and the measured costs.
#pragma once

#include <array>
#include <filesystem>
#include <functional>
#include <optional>
#include <string>
#include <vector>

#include <nlohmann/json.hpp>

#include "metalfit_bench/machine.hpp"

namespace metalfit::bench {

struct ModelCostsOptions {
    std::string material = "Au";  // whose fitted parameters the CPU kernels evaluate
    std::filesystem::path data_dir;
    std::optional<std::filesystem::path> ocio_config;
    std::filesystem::path glpreview;               // its --bench-shaders gives the software-GPU column
    std::optional<std::filesystem::path> glslang;  // glslangValidator for the SPIR-V columns
    int cpu_rounds = 31;
    double seconds_per_sample = 0.02;
    std::string command_line;
    std::function<void(const std::string&)> progress;
};

// A ratio to conductor-rgb over rounds: the median of the per-round ratios, half their interquartile range, and the
// quartiles.
struct MeasuredRatio {
    double ratio = 0;
    double noise = 0;
    std::array<double, 2> quartiles{};
};

struct ModelCostRow {
    std::string model;
    MeasuredRatio gpu;        // glpreview's pass on the software GPU
    MeasuredRatio cpu_array;  // the C++ definition over an array of 1024 μ
    int spirv_ops = 0;        // arithmetic + transcendental + texture (SpirvCounts::compute)
    double spirv_weighted = 0;
};

struct ModelCosts {
    std::string command_line;
    Machine machine;
    std::string material;
    std::string renderer, gpu_clock;  // glpreview's GL_RENDERER and frame clock
    int gpu_rounds = 0, gpu_size = 0, evaluations_per_pixel = 0;
    int cpu_rounds = 0;
    double seconds_per_sample = 0;
    std::string validator;
    std::vector<ModelCostRow> rows;  // all_models() order
    // Spearman's rank correlation over the models.
    double weighted_vs_gpu = 0, weighted_vs_cpu = 0, ops_vs_gpu = 0, ops_vs_cpu = 0, cpu_vs_gpu = 0;
};

// Throws std::runtime_error when a column cannot be measured (no glpreview, a failed run, no glslangValidator, a
// model missing from glpreview's record or without its noise): the table is all or nothing.
ModelCosts measure_model_costs(const ModelCostsOptions& options);

nlohmann::ordered_json
to_json(const ModelCosts& costs);              // schema metalfit.model-costs/1 (schemas/model-costs.schema.json)
std::string to_text(const ModelCosts& costs);  // the table and the rank correlations

}  // namespace metalfit::bench
