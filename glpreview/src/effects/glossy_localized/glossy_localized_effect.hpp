// Rough spheres with glossy 'localized' (thesis ch. 5): the captured cube downsampled to M × M area lights per face
// (downsample.frag), summed per pixel with the GGX BRDF and the sphere's Fresnel (glossy_localized.glsl).
#pragma once

#include "glpreview/effects/effect.hpp"
#include "glpreview/graph/pass_graph.hpp"
#include "glpreview/render/gpu_resources.hpp"

namespace metalfit::glpreview {

const Effect& glossy_localized_effect();

// Downsamples the captured `source` (with distances) into `target`'s M × M area lights per face.
void downsample_environment(GpuRenderer& renderer, const EnvironmentCube& source, const DownsampledCube& target);
// The downsample pass of one M (reads the captured cube, creates the downsampled cube).
graph::Handle<DownsampledCube> add_downsample_environment_pass(graph::PassGraph& graph, const Scene& scene, int m,
                                                               graph::Handle<EnvironmentCube> cube, PreviewRun* run);

}  // namespace metalfit::glpreview
