// What accuracy costs on the GPU, measured in one run so that ratios are meaningful (absolute times are context):
// - shader cost: a full-screen pass evaluating each libfit model (its single GLSL definition), and the reference
//   LUT, as a ratio to the exact conductor-rgb pass;
// - localization cost: ms per frame and error against the CPU reference for classic, box-parallax and the
//   distance impostor (secant, false position, mixed, illinois, safe-secant) at 0 … 16 iterations, in the empty and the difficult room;
// - glossy cost: roughness 0.05 … 0.8 × method (prefiltered with box-parallax or the impostor, localized M = 2, 4, 8):
//   ms per frame as a ratio to the mirror classic pass, and RMSE against the Monte-Carlo reference.
// Frames are interleaved across the variants (round-robin) and the median per variant is kept, so that drifts of
// a shared machine hit every variant alike. Both benchmarks are passes of one pass graph (add_gpu_bench_passes):
// the record asked for decides which passes run, the graph creates and frees their GL resources. Used by
// `glpreview --bench-*` and, through it, `metalfit bench`.
#pragma once

#include <optional>
#include <string>
#include <vector>

#include <nlohmann/json.hpp>

#include "glpreview/gl/gl_context.hpp"
#include "glpreview/graph/pass_graph.hpp"
#include "glpreview/render/preview.hpp"
#include "glpreview/render/sphere_fresnel.hpp"
#include "glpreview/scene/scene.hpp"

namespace metalfit::glpreview {

// Each pixel evaluates the model this many times (at different μ) so that the pass measures the model and not
// the framebuffer write; the JSON says so.
inline constexpr int kShaderBenchEvaluationsPerPixel = 16;
inline constexpr int kShaderBenchSize = 1024;

// A room of the localization benchmark: data/scenes/sheet.json ("difficult") or the same room emptied ("empty"),
// seen from close by so that the sphere fills most of the frame; its one sphere shows the reference Fresnel.
struct LocalizationRoom {
    std::string name;
    Scene scene;
};
std::vector<LocalizationRoom> localization_rooms(const std::filesystem::path& data_dir, bool quick);

// What the benchmark passes share (as PreviewRun does for a preview): the settings, the rooms (their spheres
// change reflection settings between timed frames), the GL context (null: the graph can be compiled, not run).
struct GpuBenchRun {
    PreviewOptions options;
    bool quick = false;
    GlContext* context = nullptr;
    std::vector<LocalizationRoom> rooms;
    std::optional<FresnelLibrary> library;         // made by the localization's first pass
    std::optional<FresnelLibrary> glossy_library;  // made by the glossy benchmark's first pass
};

// The records the benchmarks produce; request one, and the graph culls the other benchmark's passes.
struct GpuBenchHandles {
    graph::Handle<nlohmann::ordered_json> shaders, localization, glossy;
};
GpuBenchHandles add_gpu_bench_passes(graph::PassGraph& graph, GpuBenchRun& run);

// {"renderer", "size", "frames", "evaluations_per_pixel", "models": [{"model", "ms_per_frame", "ratio_to_conductor_rgb"}]}
nlohmann::ordered_json bench_shaders(GlContext& context, const PreviewOptions& options, bool quick);

// {"renderer", "size", "frames", "rooms": [{"room", "rows": [{"mode", "strategy", "iterations", "tolerance",
//  "mean_iterations", "ms_per_frame", "ratio_to_classic", "ratio_noise", "rmse", "mean_abs"}]}]}: iterations is the
//  limit, mean_iterations the steps the sphere's pixels took; ratio_noise the half interquartile range of the
//  per-round ratios.
nlohmann::ordered_json bench_localization(GlContext& context, const PreviewOptions& options, bool quick);

// One column of the glossy table: a rough sphere's method (or, at roughness 0, the mirror classic pass the ratios
// are taken to).
struct GlossyVariant {
    double roughness = 0;
    GlossyMethod glossy = GlossyMethod::prefiltered;
    ReflectionMode reflection = ReflectionMode::classic;  // the prefiltered lookup's localization
    int localized_size = 8;                               // M of `localized`
};
std::vector<double> glossy_bench_roughness();        // 0.05, 0.1, 0.2, 0.4, 0.8
std::vector<GlossyVariant> glossy_bench_variants();  // the mirror classic pass, then roughness × method
std::string
glossy_variant_name(const GlossyVariant& v);  // "prefiltered box-parallax", "localized M=4", "mirror classic"
// The scene of one variant: the difficult room of the localization benchmark (the camera close to its one sphere,
// gold, reference Fresnel), 128² (quick: 48²), the Monte-Carlo reference at 256 (quick: 32) samples per pixel. A
// preview of it gives the bench's RMSE in its metrics.json.
Scene glossy_bench_scene(const std::filesystem::path& data_dir, bool quick, const GlossyVariant& variant);

// {"renderer", "size", "frames", "reference_samples", "material",
//  "rows": [{"roughness", "method", "glossy", "reflection", "localized_size", "ms_per_frame", "ratio_to_mirror_classic",
//            "ratio_noise", "rmse", "mean_abs", "reference_noise"}],  (rows[0]: the mirror classic pass, its RMSE against the analytic reference)
//  "mirror_scenes": [{"scene", "size", "spheres", "ms_per_frame"}]}
nlohmann::ordered_json bench_glossy(GlContext& context, const PreviewOptions& options, bool quick);

}  // namespace metalfit::glpreview
