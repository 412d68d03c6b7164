// The ground truth of rough spheres: per pixel, the same camera ray and sphere hit as the analytic reference, then
// the GGX lobe (ggx.hpp) integrated by Monte Carlo: visible-normal samples, each reflected ray traced exactly
// through the environment (EnvironmentTracer), weighted F(v·m) · G2 / G1 with the sphere's own Fresnel (the model
// or the R_c table, as SphereFresnel evaluates it). Fixed seed per pixel, so the image does not depend on the
// number of threads; rows are spread over std::threads. Mirror spheres (roughness 0) and the background keep the
// analytic reference's pixels and a standard error of 0.
// With max_bounces = k > 1 (the scene's max_bounces) a sampled ray that meets another sphere continues from it —
// reflected about a mirror's normal with its F(μ), or sampled from a rough sphere's lobe the same way — up to k
// reflections; a mirror sphere's pixel whose mirror path reaches a rough sphere is estimated the same way. The
// lights' direct term is added at the first bounce only.
#pragma once

#include <cstdint>
#include <vector>

#include "glpreview/render/cpu_reference.hpp"

namespace metalfit::glpreview {

inline constexpr std::uint64_t kMonteCarloSeed = 20081117;  // fixed: the same scene gives the same reference

struct MonteCarloReference {
    ReferenceRender render;  // the reference image with the rough spheres' pixels estimated
    Image standard_error;    // per pixel and channel: sample standard deviation / √samples (0 where exact)
};

// `analytic` is render_reference() of the same scene; `samples` per pixel (scene.outputs.reference_samples).
// `lighting`: the direct light effects add to rough spheres (its estimate and variance added to the lobe's).
MonteCarloReference render_monte_carlo_reference(const Scene& scene, const std::vector<const SphereFresnel*>& fresnel,
                                                 const EnvironmentTracer& environment, const ReferenceRender& analytic,
                                                 int samples, int threads = 0, const CpuLighting* lighting = nullptr,
                                                 int max_bounces = 1);

}  // namespace metalfit::glpreview
