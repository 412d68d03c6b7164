// Shader cost without a GPU: a model's GLSL (the single definition, Model::glsl_source()) inside a tiny fragment
// shader, compiled to SPIR-V by glslangValidator with its size optimiser (-V -Os: calls inlined, constants folded,
// dead code removed), and the executable instructions counted per category.
//
// Categories (docs/accuracy-vs-cost.md): only instructions inside function bodies count, and not the structural ones
// (OpFunction, OpFunctionParameter, OpFunctionEnd, OpLabel, OpVariable, OpLine, OpNoLine, OpNop, OpSelectionMerge,
// OpLoopMerge). One instruction is one count whatever its vector width (a vec3 multiply is 1); the weighted count
// (SpirvCounts::weighted) counts lanes and weighs the classes.
// - arithmetic: OpSNegate … OpSMulExtended (126–152: add, sub, mul, div, mod, negate, vector × scalar, dot), the bit
//   operations (194–205), and every GLSL.std.450 extended instruction that is not transcendental (min, max, clamp,
//   mix, fma, abs, floor, step, …);
// - transcendental: the GLSL.std.450 instructions that need a special-function unit: Sin … Atan2 (13–25), Pow, Exp,
//   Log, Exp2, Log2, Sqrt, InverseSqrt (26–32), and Length, Distance, Normalize, Refract (66, 67, 69, 72: a root);
// - texture: image sampling, fetch, gather, read and write (87–99, sparse 305–315 and 320);
// - other: everything else that executes: loads and stores, access chains, composite construct / extract / shuffle,
//   comparisons and select, conversions, branches, calls, returns, extended instructions of other sets.
#pragma once

#include <cstdint>
#include <filesystem>
#include <optional>
#include <span>
#include <string>
#include <vector>

#include "libfit/models/model.hpp"

namespace metalfit::bench {

struct SpirvCounts {
    int arithmetic = 0;
    int transcendental = 0;
    int texture = 0;
    int other = 0;
    // Arithmetic, transcendental and texture instructions weighted by class and counted per vector lane (the
    // weights: spirv_cost.cpp, glsl450_weight; docs/fitting.md "Costs"): 1 per lane of an add, multiply, min, mix…,
    // 5 of a division, 4 of a square root, exp2, log2, sin, cos, 5 of exp and log, 9 of pow, 4 of a texture read.
    double weighted = 0;
    int compute() const { return arithmetic + transcendental + texture; }  // the table's "SPIR-V ops"
    int total() const { return compute() + other; }
    bool operator==(const SpirvCounts&) const = default;
};

// Counts the instructions of a SPIR-V module (little-endian words, header included). Throws std::runtime_error for
// a malformed module (bad magic, truncated or zero-length instruction).
SpirvCounts count_spirv(std::span<const std::uint32_t> words);

// The fragment shader around a model's function: its parameters from a uniform block, μ from an input, the result
// written to the output.
std::string model_fragment_shader(const Model& model);
// The same around a 1D reference LUT (texture(lut, (μ (N − 1) + 0.5) / N), N a uniform).
std::string lut_fragment_shader();
// Only the wrapper (output = the first parameter): what every row's "other" count includes.
std::string passthrough_fragment_shader();

// Compiles a fragment shader with `validator -V -Os`; throws std::runtime_error with the compiler's last message.
std::vector<std::uint32_t> compile_fragment_shader(const std::filesystem::path& validator, const std::string& source);

struct SpirvRow {
    std::string id;  // model id, "reference-lut", "wrapper"
    std::optional<SpirvCounts> counts;
    std::string error;  // when counts is empty
};

// Every model, the LUT and the bare wrapper.
std::vector<SpirvRow> spirv_costs(const std::filesystem::path& validator);

}  // namespace metalfit::bench
