// The CPU reference: analytic ray tracing of the same scene (same camera, same Fresnel), with exact mirror
// reflections. With max_bounces = 1 (the default) spheres reflect the environment only (not each other), as in the
// one-bounce GPU render, whose cube map is captured without them; with max_bounces = k a reflected ray that meets
// another sphere reflects there again (render/mirror_path.hpp), multiplying that sphere's Fresnel at that bounce's μ,
// up to k reflections, and the last reflected ray takes the environment's radiance.
#pragma once

#include <functional>
#include <vector>

#include "glpreview/io/image.hpp"
#include "glpreview/render/cpu_lighting.hpp"
#include "glpreview/render/environment.hpp"
#include "glpreview/render/sphere_fresnel.hpp"
#include "glpreview/scene/scene.hpp"

namespace metalfit::glpreview {

struct ReferenceRender {
    Image image;
    std::vector<int> sphere_id;  // per pixel (top row first): the sphere seen, −1 for the environment
};

// fresnel[i] belongs to scene.spheres[i]. Runs on `threads` threads (0: all cores). `lighting`: what effects add
// (emitters seen by camera and mirror rays; the room's light is the tracer's). `max_bounces`: 1 … 8 (the scene's
// max_bounces; std::invalid_argument otherwise); a reflected ray meets the spheres before any emitter.
ReferenceRender render_reference(const Scene& scene, const std::vector<const SphereFresnel*>& fresnel,
                                 const EnvironmentTracer& environment, int threads = 0,
                                 const CpuLighting* lighting = nullptr, int max_bounces = 1);

// What the analytic references share: every pixel's camera ray and, where it meets a sphere, its mirror path
// (render/mirror_path.hpp, up to max_bounces reflections); `shade(path, light)` turns a path and the light at its
// end (an emitter's, else the environment's) into the pixel's radiance. Pixels of the environment take its radiance.
// std::invalid_argument when max_bounces is outside 1 … kMaxPathBounces.
struct MirrorPath;
ReferenceRender render_mirror_paths(const Scene& scene, const EnvironmentTracer& environment, int max_bounces,
                                    int threads, const CpuLighting* lighting,
                                    const std::function<RGB(const MirrorPath& path, const RGB& light)>& shade);

}  // namespace metalfit::glpreview
