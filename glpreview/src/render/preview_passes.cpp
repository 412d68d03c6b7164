#include "glpreview/render/preview_passes.hpp"

#include <algorithm>
#include <cmath>

#include "frame_timing.hpp"
#include "glpreview/effects/registry.hpp"
#include "glpreview/io/image_text.hpp"
#include "glpreview/render/environment.hpp"
#include "glpreview/render/exr_metadata.hpp"
#include "glpreview/render/frame_inputs.hpp"
#include "glpreview/render/monte_carlo_reference.hpp"
#include "glpreview/render/scene_colour.hpp"
#include "glpreview/render/sphere_metrics.hpp"
#include "libfit/base/atomic_file.hpp"
#include "libfit/base/errors.hpp"
#include "libfit/base/number_text.hpp"
#include "libfit/base/sample_statistics.hpp"
#include "libfit/base/text.hpp"

namespace metalfit::glpreview {
namespace {

using graph::Builder;
using graph::Handle;
using graph::PassGraph;
using graph::Processor;
using graph::Resources;

using graph::Out;

struct Empty {};

const Image& image_of(const Image& image) { return image; }
const Image& image_of(const ReferenceRender& render) { return render.image; }

// The caption's text: what the image shows, then the display transform (ASCII: OpenImageIO draws a glyph per byte)
// and the exposure.
std::string caption_text(const std::string& caption, const PreviewRun& run) {
    std::string display = run.display ? run.display->description() : std::string();
    for (std::size_t at; (at = display.find("\u2192")) != std::string::npos;) display.replace(at, 3, "->");
    const double stops = std::log2(run.exposure);
    return caption + "; " + display + ", exposure " + (std::signbit(stops) ? "" : "+") + significant_text(stops, 6) +
           " EV";  // printf's "%+g EV"
}

template <typename T>
void add_image_file(PassGraph& graph, const std::string& file, Handle<T> image, PreviewRun* run,
                    PngExposure exposure = PngExposure::apply, const std::string& caption = {}) {
    const bool png = std::filesystem::path(file).extension() == ".png";
    graph.add_pass<Empty>(
        {"write " + file, png ? "through the OCIO display transform" : "linear half-float EXR", Processor::cpu},
        [&](Builder& b, Empty&) {
            b.read(image);
            b.write_file(file);
        },
        [run, file, image, png, exposure, caption](const Empty&, Resources& r) {
            if (run->output_dir.empty()) return;
            const std::filesystem::path path = run->output_file(file);
            if (png && caption.empty() && (exposure == PngExposure::already_applied || run->exposure == 1.0)) {
                write_png(path, image_of(r.get(image)), *run->display);
            } else if (png) {
                Image shown = exposure == PngExposure::apply ? exposed(image_of(r.get(image)), run->exposure)
                                                             : image_of(r.get(image));
                if (!caption.empty()) {
                    const int band = caption_band_height(shown.height);
                    draw_text(shown, {{0, 0, shown.width, band, caption_text(caption, *run), band - 2}});
                }
                write_png(path, shown, *run->display);
            } else {
                write_exr(path, image_of(r.get(image)), run->exr_colour ? &*run->exr_colour : nullptr,
                          image_metadata(run->exr_metadata, file));
            }
        });
}

// The frame times: apart from metrics.json, which is then the same bytes on every run of the same scene.
Json timings_json(const PreviewRun& run, const FrameTimes& frame_ms) {
    Json j;
    j["schema"] = "metalfit.preview-timings/1";
    j["scene"] = run.scene.file.filename().string();
    j["renderer"] = run.renderer_name;
    j["size"] = {run.scene.width, run.scene.height};
    j["clock"] = clock_name(clock_for_renderer(run.renderer_name));
    j["ms_per_frame"] = frame_ms.empty() ? 0.0 : median(frame_ms);
    j["frame_ms"] = frame_ms;
    return j;
}

}  // namespace

void PreviewRun::open_gl() {
    if (gpu) return;
    if (!context) context = &own_context.emplace(GlContext::create());
    renderer_name = context->renderer();
    gpu.emplace(scene, features ? *features : plan_features(scene), fresnel, nullptr, &context->programs());
}

GpuRenderer& PreviewRun::renderer() {
    open_gl();
    return *gpu;
}

std::filesystem::path PreviewRun::output_file(const std::string& name) {
    if (!staging) {
        staging.emplace(output_dir);
        if (scene.outputs.png) display = DisplayTransform::create(ocio, scene.space);
    }
    if (!display && std::filesystem::path(name).extension() == ".png")
        display = DisplayTransform::create(ocio, scene.space);
    written.push_back(output_dir / name);
    return staging->file(name);
}

void PreviewRun::commit_outputs() {
    if (staging) staging->commit();
}

SceneInputs import_scene(PassGraph& graph, const Scene& scene) {
    return {graph.import <const Scene*>("environment-description", &scene),
            graph.import <const Scene*>("materials", &scene), graph.import <const Scene*>("camera", &scene)};
}

void add_image_file_pass(PassGraph& graph, const std::string& file, Handle<Image> image, PreviewRun* run,
                         PngExposure exposure, const std::string& caption) {
    add_image_file(graph, file, image, run, exposure, caption);
}

int caption_band_height(int height) { return std::clamp(height / 16, 8, 24); }

Image exposed(const Image& image, double exposure) {
    Image out = image;
    for (float& v : out.rgb) v = static_cast<float>(v * exposure);
    return out;
}
void add_image_file_pass(PassGraph& graph, const std::string& file, Handle<ReferenceRender> image, PreviewRun* run,
                         const std::string& caption) {
    add_image_file(graph, file, image, run, PngExposure::apply, caption);
}

namespace {

// A pass writing `file` (indented JSON) from the resource `from`, as `to_json` makes it of that resource.
template <typename T, typename ToJson>
void add_json_file(PassGraph& graph, const std::string& file, const std::string& why, Handle<T> from, PreviewRun* run,
                   ToJson to_json) {
    graph.add_pass<Empty>(
        {"write " + file, why, Processor::cpu},
        [&](Builder& b, Empty&) {
            b.read(from);
            b.write_file(file);
        },
        [run, file, from, to_json](const Empty&, Resources& r) {
            if (run->output_dir.empty()) return;
            write_file_atomically(run->output_file(file), to_json(r.get(from)).dump(2) + "\n");
        });
}

}  // namespace

void add_json_file_pass(PassGraph& graph, const std::string& file, const std::string& why, Handle<Json> json,
                        PreviewRun* run) {
    add_json_file(graph, file, why, json, run, [](const Json& j) -> const Json& { return j; });
}

PreviewHandles add_preview_passes(PassGraph& graph, const Scene& scene, const Features& f, PreviewRun* run) {
    PreviewHandles h;
    const SceneInputs in = import_scene(graph, scene);
    FrameInputs frame;
    frame.read(in.camera);
    FrameInputs environment;  // what the capture reads (the lights' shadow maps)
    // The effects' passes the frames read (effects/registry.hpp), and what each hands to the frames.
    PreviewGraph effects{graph, scene, f, in, run, frame, environment, h};
    for (const Effect* effect : all_effects()) effect->add_frame_input_passes(effects);

    // beauty: one frame of every sphere with its shader variant.
    h.beauty = graph
                   .add_pass<Out<Image>>(
                       {"beauty",
                        std::to_string(f.shader_variants.size()) + " sphere shader variant(s): " +
                            join({f.shader_variants.begin(), f.shader_variants.end()}, " | "),
                        Processor::gpu},
                       [&](Builder& b, Out<Image>& d) {
                           frame.declare(b);
                           d.out = b.produce<Image>("beauty-image");
                       },
                       [run, frame](const Out<Image>& d, Resources& r) {
                           frame.bind(run->renderer(), r);
                           r.emplace(d.out, run->renderer().render());
                       })
                   .out;
    // The passes that read the beauty frame (references, diagnostics, metrics), in registry order.
    for (const Effect* effect : all_effects()) effect->add_output_passes(effects);

    // Sinks: the files asked for, each bound to its writer.
    const Outputs& o = scene.outputs;
    std::vector<std::string> formats;
    if (o.exr) formats.push_back("exr");
    if (o.png) formats.push_back("png");
    // The PNGs' captions (outputs.labels): what each shows; the EXRs are the bare images.
    const auto caption = [&o](const std::string& format, const char* text) {
        return format == "png" && o.labels ? std::string(text) : std::string();
    };
    for (const auto& format : formats)
        if (o.beauty)
            add_image_file_pass(graph, "beauty." + format, h.beauty, run, PngExposure::apply,
                                caption(format, "beauty: GPU preview"));
    for (const auto& format : formats)
        if (o.reference)
            add_image_file_pass(graph, "reference." + format, h.reference, run,
                                caption(format, "reference: CPU ray trace"));
    for (const auto& format : formats)
        if (o.difference)
            add_image_file_pass(graph, "difference." + format, h.difference, run, PngExposure::apply,
                                caption(format, "difference: |beauty - reference|"));
    if (o.reference && h.reference_standard_error)
        add_image_file_pass(graph, "reference-stderr.exr", *h.reference_standard_error, run);
    if (o.localization) add_image_file_pass(graph, "localization.exr", h.localization, run);
    if (o.metrics) {
        add_json_file_pass(graph, "metrics.json", "asked for", h.metrics, run);
        add_json_file(graph, "timings.json", "asked for (metrics: the frame times, apart from metrics.json)",
                      h.frame_times, run, [run](const FrameTimes& frame_ms) { return timings_json(*run, frame_ms); });
    }
    return h;
}

void skip_unneeded_effects(PassGraph& graph) { graph.skip("SH irradiance", "metals have no diffuse lobe"); }

}  // namespace metalfit::glpreview
