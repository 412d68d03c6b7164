// Rough spheres with glossy 'prefiltered' (split sum): the captured cube GGX-prefiltered into a mip chain
// (prefilter.frag), times each sphere's own DFG table over (μ, roughness) (render/dfg_table.hpp).
#pragma once

#include "glpreview/effects/effect.hpp"
#include "glpreview/graph/pass_graph.hpp"
#include "glpreview/render/gpu_resources.hpp"

namespace metalfit::glpreview {

const Effect& glossy_prefiltered_effect();

// GGX-prefilters the captured `source` (made with mipmaps) into `target`, every face and level.
void prefilter_environment(GpuRenderer& renderer, const EnvironmentCube& source, const PrefilteredCube& target);
// The prefilter pass (reads the captured cube, creates the prefiltered cube); `why` names the spheres it serves.
graph::Handle<PrefilteredCube> add_prefilter_environment_pass(graph::PassGraph& graph, const Scene& scene,
                                                              graph::Handle<EnvironmentCube> cube, PreviewRun* run);

}  // namespace metalfit::glpreview
