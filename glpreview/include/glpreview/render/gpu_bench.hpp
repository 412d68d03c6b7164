// What accuracy costs on the GPU, measured in one run so that ratios are meaningful (absolute times are context):
// - shader cost: a full-screen pass evaluating each libfit model (its single GLSL definition), and the reference
//   LUT, as a ratio to the exact conductor-rgb pass;
// - localization cost: ms per frame and error against the CPU reference for classic, box-parallax and the
//   distance impostor (secant, false position, mixed) at 0 … 16 iterations, in the empty and the difficult room.
// Frames are interleaved across the variants (round-robin) and the median per variant is kept, so that drifts of
// a shared machine hit every variant alike. Used by `glpreview --bench-*` and, through it, `metalfit bench`.
#pragma once

#include <filesystem>

#include <nlohmann/json.hpp>

#include "glpreview/gl/gl_context.hpp"
#include "glpreview/render/preview.hpp"

namespace metalfit::glpreview {

// Each pixel evaluates the model this many times (at different μ) so that the pass measures the model and not
// the framebuffer write; the JSON says so.
inline constexpr int kShaderBenchEvaluationsPerPixel = 16;

// {"renderer", "size", "frames", "evaluations_per_pixel", "models": [{"model", "ms_per_frame", "ratio_to_conductor_rgb"}]}
nlohmann::ordered_json bench_shaders(GlContext& context, bool quick);

// {"renderer", "size", "frames", "rooms": [{"room", "rows": [{"mode", "strategy", "iterations", "ms_per_frame",
//  "ratio_to_classic", "rmse", "mean_abs"}]}]}; the rooms are data/scenes/sheet.json and the same room emptied,
// seen from close by so that the sphere fills most of the frame.
nlohmann::ordered_json bench_localization(GlContext& context, const PreviewOptions& options, bool quick);

}  // namespace metalfit::glpreview
