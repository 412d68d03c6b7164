#include "glpreview/render/plan.hpp"

#include "glpreview/render/preview_passes.hpp"

#include <algorithm>
#include <map>
#include <sstream>

#include "glpreview/scene/glossy_choice.hpp"
#include "libfit/base/number_text.hpp"
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
    bool rough = false;
    for (std::size_t i = 0; i < scene.spheres.size(); ++i) {
        const Sphere& s = scene.spheres[i];
        if (!s.rough()) continue;
        if (!rough) out << "glossy (the method of each rough sphere):\n";
        rough = true;
        out << "  sphere " << i << " (roughness " << significant_text(s.roughness, 3) << ", '"
            << to_string(s.glossy_request) << "'): " << to_string(s.glossy) << ": "
            << choose_glossy_method(s.roughness, s.glossy_request).reason << "\n";
    }
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
