// What a model costs to evaluate in a shader, for choosing the cheapest model that meets an error budget (budget.hpp).
// Either the built-in table (SPIR-V op counts of each model's GLSL, as `metalfit bench` counts them) or the ratios a
// `metalfit bench --json` run measured on the user's machine (GPU shader ratios when every model has one, else the
// CPU scalar ratios).
#pragma once

#include <filesystem>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

namespace metalfit {

struct ModelCost {
    std::string model;  // model id
    double cost = 0;    // lower is cheaper; only the order and ties matter
};

struct CostTable {
    // Which table decided, for records and messages ("built-in: SPIR-V ops (glslangValidator -V -Os, metalfit bench)",
    // "bench.json: GPU shader ratio to conductor-rgb").
    std::string source;
    std::string unit;  // "SPIR-V ops", "x conductor-rgb (GPU)", "x conductor-rgb (CPU scalar)"
    std::vector<ModelCost> costs;

    // The cost of a model, if the table has it.
    std::optional<double> cost_of(std::string_view model) const;
};

// The built-in table: arithmetic + transcendental SPIR-V instructions of each registered model's GLSL inside the
// bench's fragment shader, compiled with glslangValidator -V -Os (docs/accuracy-vs-cost.md). A test
// (test_bench_spirv.cpp) recounts them with the bench and fails when a model's GLSL changes without this table.
CostTable builtin_cost_table();

// The table of a `metalfit bench --json` report (schema metalfit.bench/1): each model row's `shader_ratio` when every
// model row has one (GPU), else its `ratio_scalar` (CPU). Throws InputError naming the file and the field for a file
// that is not such a report. Its `source` names the file by record_path against `data_dir` (never absolutely).
CostTable cost_table_from_bench_json(const std::filesystem::path& file, const std::filesystem::path& data_dir = {});

}  // namespace metalfit
