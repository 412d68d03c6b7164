// Plan first, then run only what the scene needs (DESIGN.md): Scene → Features (a pure function), then a pass list
// built from the features and the requested outputs, where passes nobody reads are culled, frame-graph style.
#pragma once

#include <set>
#include <string>
#include <vector>

#include "glpreview/scene/scene.hpp"

namespace metalfit::glpreview {

// What the scene calls for. Every flag has a reason string for --explain.
struct Features {
    bool environment_capture = false;  // a procedural room (or sphere room): ray-cast by GL into the cube map
    bool distance_channel = false;     // some sphere uses the distance impostor: the cube map stores distances
    bool equirect_image = false;       // an image environment at infinity (read with OpenImageIO)
    bool reference_lut = false;        // some sphere shows the exact reference curve (1D RGB texture)
    bool model_fits = false;           // some sphere uses a libfit model (fit or closed-form parameters)
    bool cpu_reference = false;        // the ray-traced reference image (asked for, or needed by difference/metrics)
    bool difference_image = false;     // |beauty − reference| (asked for)
    bool metrics = false;              // metrics.json: per-sphere error and ms per frame
    bool prefiltered_map = false;      // glossy reflections: no sphere is rough (pure mirrors), never needed yet
    bool irradiance_sh = false;        // diffuse lobe: metals have none, never needed yet
    std::set<std::string> models;      // libfit model ids used
    std::set<std::string> shader_variants;  // #define sets of the sphere shader, one per distinct variant
};

Features plan_features(const Scene& scene);

// One pass: what it reads and writes (resource names), and why it exists.
struct Pass {
    std::string name;
    std::string why;
    std::vector<std::string> reads;
    std::vector<std::string> writes;
    bool gpu = false;
};

struct SkippedPass {
    std::string name;
    std::string why;
};

struct Plan {
    Features features;
    std::vector<Pass> passes;          // in execution order, culled
    std::vector<SkippedPass> skipped;  // what was not planned or was culled, and why
    std::vector<std::string> outputs;  // sink resources (files)
    bool runs(const std::string& pass_name) const;
};

// Builds every candidate pass from the features, then keeps only those whose writes reach a requested output.
Plan build_plan(const Scene& scene);

// The plan as text: each pass, why it runs, what it reads and writes; then what was skipped and why.
std::string explain(const Plan& plan, const Scene& scene);

// The shader #define of an environment type: "ENV_ROOM", "ENV_SPHERE_ROOM" or "ENV_EQUIRECT".
const char* environment_define(EnvironmentType type);

// The sphere shader's #defines for one sphere (sorted, one per line), e.g. "REFLECTION_DISTANCE_IMPOSTOR",
// "STRATEGY_FALSE_POSITION", "NITER 4", "FRESNEL_MODEL f82-tint", "ENV_ROOM".
std::vector<std::string> sphere_defines(const Scene& scene, const Sphere& sphere);

}  // namespace metalfit::glpreview
