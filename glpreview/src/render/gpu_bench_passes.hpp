// The passes of the three GPU benchmarks (gpu_bench.hpp), one file per benchmark.
#pragma once

#include <nlohmann/json.hpp>

#include "glpreview/graph/pass_graph.hpp"
#include "glpreview/render/gpu_bench.hpp"

namespace metalfit::glpreview {

// model-cost-programs → shader-timing (its colour target and synthetic LUT made by the graph) → shader-record.
graph::Handle<nlohmann::ordered_json> add_shader_cost_passes(graph::PassGraph& graph, GpuBenchRun& run);
// bench-fresnel → per room: cpu-reference, capture-environment (its cube made by the graph), localization-timing →
// localization-record.
graph::Handle<nlohmann::ordered_json> add_localization_cost_passes(graph::PassGraph& graph, GpuBenchRun& run);
// glossy-fresnel → glossy-references (Monte Carlo per roughness) → glossy-timing (its renderers, one per cube format,
// and the shipped mirror scenes) → glossy-record.
graph::Handle<nlohmann::ordered_json> add_glossy_cost_passes(graph::PassGraph& graph, GpuBenchRun& run);

}  // namespace metalfit::glpreview
