#include "glpreview/render/plan.hpp"

#include "glpreview/render/preview_passes.hpp"

#include <algorithm>
#include <map>
#include <sstream>

#include "libfit/base/text.hpp"

namespace metalfit::glpreview {
bool Plan::runs(const std::string& pass_name) const {
    return std::any_of(passes.begin(), passes.end(), [&](const Pass& p) { return p.name == pass_name; });
}

Plan plan_of(const graph::PassGraph& graph, const Features& features) {
    Plan plan;
    plan.features = features;
    for (const graph::CompiledPass& p : graph.passes())
        plan.passes.push_back({p.name, p.why, p.reads, p.writes, p.processor == graph::Processor::gpu});
    plan.skipped = graph.skipped();
    plan.outputs = graph.output_files();
    return plan;
}

Plan build_plan(const Scene& scene) {
    graph::PassGraph graph;
    const Features features = plan_features(scene);
    add_preview_passes(graph, scene, features, nullptr);
    graph.compile();
    skip_unneeded_effects(graph);
    return plan_of(graph, features);
}

std::string explain(const Plan& plan, const Scene& scene) {
    std::ostringstream out;
    out << "scene " << scene.file.string() << ": " << scene.width << "x" << scene.height << ", " << scene.spheres.size()
        << " sphere(s), environment " << to_string(scene.environment.type) << "\n";
    out << "passes:\n";
    int i = 1;
    for (const Pass& p : plan.passes) {
        out << "  " << i++ << ". " << p.name << (p.gpu ? " [GPU]" : " [CPU]") << ": " << p.why << "\n";
        if (!p.reads.empty()) out << "       reads " << join(p.reads) << "\n";
        out << "       writes " << join(p.writes) << "\n";
    }
    out << "skipped:\n";
    for (const SkippedPass& s : plan.skipped) out << "  - " << s.name << ": " << s.why << "\n";
    return out.str();
}

}  // namespace metalfit::glpreview
