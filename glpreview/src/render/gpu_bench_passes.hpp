// The passes of the three GPU benchmarks (gpu_bench.hpp), one file per benchmark.
#pragma once

#include <nlohmann/json.hpp>

#include "glpreview/graph/pass_graph.hpp"
#include "glpreview/render/gpu_bench.hpp"

namespace metalfit::glpreview {

// The first pass of the localization and glossy benchmarks: the benchmark sphere's reference R_c(μ) from libfit (the
// first sphere of the scene `first_scene` returns when the pass runs), its library kept in `library` (a member of
// the run, so that the Fresnel outlives the graph's execution).
template <class FirstScene>
graph::Handle<const SphereFresnel*>
add_bench_fresnel_pass(graph::PassGraph& graph, const std::string& name, const std::string& purpose, GpuBenchRun& run,
                       std::optional<FresnelLibrary>& library, FirstScene first_scene) {
    const graph::Handle<const GpuBenchRun*> materials = graph.import <const GpuBenchRun*>(name + "-materials", &run);
    struct FresnelData {
        graph::Handle<const SphereFresnel*> out;
    };
    return graph
        .add_pass<FresnelData>(
            {name, purpose, graph::Processor::cpu},
            [&](graph::Builder& b, FresnelData& d) {
                b.read(materials);
                d.out = b.produce<const SphereFresnel*>(name);
            },
            [&run, &library, first_scene](const FresnelData& d, graph::Resources& r) {
                const Scene& scene = first_scene();
                FresnelLibrary& made = library.emplace(run.options.data_dir, run.options.ocio, scene.space, scene.file);
                r.emplace(d.out, &made.get(scene.spheres.at(0), "spheres[0]"));
            })
        .out;
}

// model-cost-programs → shader-timing (its colour target and synthetic LUT made by the graph) → shader-record.
graph::Handle<nlohmann::ordered_json> add_shader_cost_passes(graph::PassGraph& graph, GpuBenchRun& run);
// bench-fresnel → per room: cpu-reference, capture-environment (its cube made by the graph), localization-timing →
// localization-record.
graph::Handle<nlohmann::ordered_json> add_localization_cost_passes(graph::PassGraph& graph, GpuBenchRun& run);
// glossy-fresnel → glossy-references (Monte Carlo per roughness) → glossy-timing (its renderers, one per cube format,
// and the shipped mirror scenes) → glossy-record.
graph::Handle<nlohmann::ordered_json> add_glossy_cost_passes(graph::PassGraph& graph, GpuBenchRun& run);

}  // namespace metalfit::glpreview
