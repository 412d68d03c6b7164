// What a model costs to evaluate in a shader, for choosing the cheapest model that meets an error budget (budget.hpp).
// Either the built-in table (data/model-costs.json, embedded at build time: each model's shader measured on the
// software GPU, llvmpipe, as a ratio to conductor-rgb; scripts/measure-model-costs.sh regenerates it) or the ratios a
// `metalfit bench --json` (or `--model-costs --json`) run measured on the user's machine.
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
    // Which table decided, for records and messages ("built-in (data/model-costs.json): measured shader cost on
    // llvmpipe, …", "bench.json: GPU shader ratio to conductor-rgb").
    std::string source;
    std::string unit;  // "x conductor-rgb (llvmpipe)", "x conductor-rgb (GPU)", "x conductor-rgb (CPU)"
    std::vector<ModelCost> costs;

    // The cost of a model, if the table has it.
    std::optional<double> cost_of(std::string_view model) const;
};

// The built-in table: the `cost` column of data/model-costs.json (llvmpipe: each model's full-screen shader pass on
// Mesa's software GPU, median ratio to conductor-rgb's over interleaved rounds; docs/fitting.md "Costs"). Tests
// (ModelCost.*, CompiledSpirv.*) check that it covers the registry and that its SPIR-V columns are the bench's count.
CostTable builtin_cost_table();

// The table of a `metalfit bench --json` report (schema metalfit.bench/1): each model row's `shader_ratio` when every
// model row has one (GPU), else its `ratio_scalar` (CPU); or of a `metalfit bench --model-costs --json` document
// (metalfit.model-costs/1): its `cost` column. Throws InputError naming the file and the field for a file
// that is not such a report. Its `source` names the file by record_path against `data_dir` (never absolutely).
CostTable cost_table_from_bench_json(const std::filesystem::path& file, const std::filesystem::path& data_dir = {});

}  // namespace metalfit
