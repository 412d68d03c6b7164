// What a scene calls for (docs/preview.md, "Plan first, then run only what the scene needs"): a pure function of the scene, unit-tested without GL; the
// preview's passes are added to the graph from these flags.
#pragma once

#include <set>
#include <string>
#include <vector>

#include "glpreview/scene/scene.hpp"

namespace metalfit::glpreview {

// What the scene calls for. Every flag has a reason string for --explain.
struct Features {
    bool environment_capture =
        false;  // a procedural room, sphere room or an equirect on its proxy: ray-cast by GL into the cube map
    bool distance_channel = false;  // some sphere uses the distance impostor: the cube map stores distances
    bool equirect_image = false;    // an image environment, at infinity or on a proxy (read with OpenImageIO)
    bool reference_lut = false;     // some sphere shows the exact reference curve (1D RGB texture)
    bool model_fits = false;        // some sphere uses a libfit model (fit or closed-form parameters)
    bool cpu_reference = false;     // the ray-traced reference image (asked for, or needed by difference/metrics)
    bool difference_image = false;  // |beauty − reference| (asked for)
    bool fit_error = false;  // some sphere uses a model and difference or metrics is asked: the reference-curve frame
    bool metrics = false;    // metrics.json: per-sphere error and ms per frame
    bool localization_image = false;  // localization.exr: steps taken and final |ρ − 1| per pixel (asked for)
    bool prefiltered_map = false;  // some sphere is rough with glossy 'prefiltered': the GGX-prefiltered cube mip chain
    std::set<int> downsample_sizes;  // M of the rough spheres with glossy 'localized': one downsampled cube each
    bool monte_carlo_reference =
        false;                     // the CPU reference is needed and some sphere is rough: its lobe by Monte Carlo
    bool irradiance_sh = false;    // diffuse lobe: metals have none, never needed yet
    std::set<std::string> models;  // libfit model ids used
    std::set<std::string>
        dfg_models;  // Fresnel names ("reference" or a model id) of the rough prefiltered spheres: one DFG pass each
    std::set<std::string> shader_variants;  // #define sets of the sphere shader, one per distinct variant
};

Features plan_features(const Scene& scene);
// What a rough sphere's glossy method needs (the prefiltered mip chain and its DFG table, or the downsampled cube of
// its M and the distance channel); nothing for a mirror. Part of plan_features; the sheet adds each column's.
void add_glossy_features(Features& features, const Sphere& sphere);

// The shader #define of an environment: "ENV_ROOM", "ENV_SPHERE_ROOM", "ENV_EQUIRECT" (at infinity), or
// "ENV_EQUIRECT_BOX" / "ENV_EQUIRECT_SPHERE" (an equirect on its proxy).
const char* environment_define(const Environment& environment);

// "STRATEGY_SECANT", ... "STRATEGY_SAFE_SECANT".
const char* strategy_define(Strategy strategy);
// A GLSL float literal of `value` ("0.0001", "0.0", "1e-05").
std::string glsl_float(double value);
// The localized sum splits each of the 6 M² area lights into k × k sub-lights where the GGX lobe is narrower than a
// light: k = 6 / (α M) rounded to the nearest integer (each sub-light about α/3 wide in face coordinates, which span
// 2), α = roughness², clamped to [1, ⌈16 / M⌉] so that k M stays near the finest M a scene allows (16). Measured in
// a white furnace (docs/preview.md, "Rough spheres").
int localized_subdivisions(double roughness, int m);

// The names of a sphere's shader variant: its builder's labels (render/sphere_shader.hpp), sorted, e.g. "REFLECTION_DISTANCE_IMPOSTOR",
// "STRATEGY_FALSE_POSITION", "NITER 4", "TOLERANCE 0.0001", "FRESNEL_MODEL f82-tint", "ENV_ROOM".
std::vector<std::string> sphere_defines(const Scene& scene, const Sphere& sphere);

}  // namespace metalfit::glpreview
