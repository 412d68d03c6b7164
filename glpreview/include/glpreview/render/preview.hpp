// Runs a scene's pass graph (render/preview_passes.hpp): only the passes the requested outputs need, in order; writes
// the requested files into a folder.
#pragma once

#include <filesystem>
#include <functional>
#include <memory>
#include <optional>
#include <string>
#include <vector>

#include <nlohmann/json.hpp>

#include "glpreview/gl/gl_context.hpp"
#include "glpreview/io/image.hpp"
#include "glpreview/render/cpu_reference.hpp"
#include "glpreview/render/plan.hpp"
#include "glpreview/scene/scene.hpp"
#include "libfit/color/color_space.hpp"

namespace metalfit::glpreview {

struct PreviewOptions {
    std::filesystem::path data_dir;    // libfit's built-in database
    OcioConfigChoice ocio;             // for the reference curves and the PNG display transform
    std::filesystem::path output_dir;  // empty: write nothing (tests)
    int threads = 0;                   // CPU reference threads (0: all cores)
    double exposure_ev = 0;            // PNGs only: radiance × 2^exposure_ev before the display transform (finite)
};

struct PreviewResult {
    Plan plan;
    std::string renderer;  // GL_RENDERER, "" when no GPU pass ran
    std::optional<Image> beauty;
    std::optional<ReferenceRender> reference;
    std::optional<Image> reference_standard_error;  // the Monte-Carlo reference's, when a sphere is rough
    std::optional<Image> difference;
    std::optional<Image> fit_reference;  // the frame with the exact curves, when some sphere uses a model
    std::optional<Image> localization;   // GpuRenderer::render_localization(), when metrics or the file ran it
    std::vector<double> frame_ms;
    nlohmann::ordered_json metrics;  // as written to metrics.json (null when not asked for)
    std::vector<std::filesystem::path> written;
};

// `context` may be null: one is created when a GPU pass runs (and only then). `before_commit`, when given, sees the
// result after every pass ran and before the files are switched into the output folder (the CLI prints it there and
// checks stdout: a stdout that fails writes nothing); what it throws leaves the folder as it was.
PreviewResult run_preview(const Scene& scene, const PreviewOptions& options, GlContext* context = nullptr,
                          const std::function<void(const PreviewResult&)>& before_commit = {});

}  // namespace metalfit::glpreview
