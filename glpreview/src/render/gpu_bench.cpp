#include "glpreview/render/gpu_bench.hpp"

#include "gpu_bench_passes.hpp"

namespace metalfit::glpreview {
namespace {

using Json = nlohmann::ordered_json;

// Builds both benchmarks' passes, requests one record (the graph culls the other's passes) and runs them.
Json run_benchmark(GlContext& context, const PreviewOptions& options, bool quick,
                   graph::Handle<Json> GpuBenchHandles::*benchmark) {
    GpuBenchRun run{options, quick, &context, localization_rooms(options.data_dir, quick), {}, {}};
    graph::PassGraph graph;
    const GpuBenchHandles records = add_gpu_bench_passes(graph, run);
    graph.request(records.*benchmark);
    graph.compile();
    graph.execute();
    return *graph.result(records.*benchmark);
}

}  // namespace

GpuBenchHandles add_gpu_bench_passes(graph::PassGraph& graph, GpuBenchRun& run) {
    GpuBenchHandles records;
    records.shaders = add_shader_cost_passes(graph, run);
    records.localization = add_localization_cost_passes(graph, run);
    records.glossy = add_glossy_cost_passes(graph, run);
    return records;
}

Json bench_shaders(GlContext& context, const PreviewOptions& options, bool quick) {
    return run_benchmark(context, options, quick, &GpuBenchHandles::shaders);
}

Json bench_localization(GlContext& context, const PreviewOptions& options, bool quick) {
    return run_benchmark(context, options, quick, &GpuBenchHandles::localization);
}

Json bench_glossy(GlContext& context, const PreviewOptions& options, bool quick) {
    return run_benchmark(context, options, quick, &GpuBenchHandles::glossy);
}

}  // namespace metalfit::glpreview
