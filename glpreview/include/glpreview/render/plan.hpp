// Plan first, then run only what the scene needs (docs/preview.md): Scene → Features (render/features.hpp, a pure
// function), then the preview's pass graph (render/preview_passes.hpp) compiled from the requested outputs, where
// passes nobody reads are culled. A Plan is what --explain prints of the compiled graph.
#pragma once

#include <set>
#include <string>
#include <vector>

#include "glpreview/graph/pass_graph.hpp"
#include "glpreview/render/features.hpp"
#include "glpreview/scene/scene.hpp"

namespace metalfit::glpreview {

// One kept pass: what it reads and writes (resource names), and why it exists.
struct Pass {
    std::string name;
    std::string why;
    std::vector<std::string> reads;
    std::vector<std::string> writes;
    bool gpu = false;
};

using SkippedPass = graph::SkippedPass;

struct Plan {
    Features features;
    std::vector<Pass> passes;          // in execution order, culled
    std::vector<SkippedPass> skipped;  // what was not planned or was culled, and why
    std::vector<std::string> outputs;  // sink resources (files)
    bool runs(const std::string& pass_name) const;
};

// The preview graph of the scene, compiled without running it (no GL).
Plan build_plan(const Scene& scene);
// What --explain shows of a compiled graph.
Plan plan_of(const graph::PassGraph& graph, const Features& features);

// The plan as text: each pass, why it runs, what it reads and writes; then what was skipped and why.
std::string explain(const Plan& plan, const Scene& scene);

}  // namespace metalfit::glpreview
