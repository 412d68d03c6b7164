// The passes of a preview, added to a pass graph from the scene's features (render/features.hpp). Each add_*
// function is one pass: its setup declares what it reads and writes, its execute does the work through a
// PreviewRun. With a null run the graph can be compiled and explained but not executed (build_plan, --explain).
#pragma once

#include <filesystem>
#include <functional>
#include <map>
#include <memory>
#include <optional>
#include <string>
#include <vector>

#include <nlohmann/json.hpp>

#include "glpreview/gl/gl_context.hpp"
#include "glpreview/graph/pass_graph.hpp"
#include "glpreview/io/image.hpp"
#include "glpreview/io/image_io.hpp"
#include "glpreview/render/cpu_reference.hpp"
#include "glpreview/render/delta_e_view.hpp"
#include "glpreview/render/dfg_table.hpp"
#include "glpreview/render/features.hpp"
#include "glpreview/render/frame_inputs.hpp"
#include "glpreview/render/gpu_renderer.hpp"
#include "glpreview/render/gpu_resources.hpp"
#include "glpreview/render/output_staging.hpp"
#include "glpreview/render/rgb_uplift.hpp"
#include "glpreview/render/room_light_maps.hpp"
#include "glpreview/render/spectral_fresnel.hpp"
#include "glpreview/render/sphere_fresnel.hpp"
#include "libfit/color/color_space.hpp"

namespace metalfit::glpreview {

using FrameTimes = std::vector<double>;
using Json = nlohmann::ordered_json;
// The Fresnel data of the spheres of one kind (reference LUTs or model parameters); null for the other kind.
struct FresnelSet {
    std::vector<const SphereFresnel*> spheres;
};

// What the passes of one run share: the scene, its resolved Fresnel data, the GL context and renderer (made by the
// first GPU pass) and the output folder (made by the first file written).
struct PreviewRun {
    const Scene& scene;
    std::filesystem::path output_dir;  // empty: write nothing
    OcioConfigChoice ocio;
    int threads = 0;
    std::vector<const SphereFresnel*> fresnel;  // fresnel[i] of scene.spheres[i]
    GlContext* context = nullptr;               // the caller's, or own_context
    std::optional<GlContext> own_context;
    std::string renderer_name;  // GL_RENDERER once a GPU pass ran
    std::optional<GpuRenderer> gpu;
    std::optional<DisplayTransform> display;
    std::optional<ExrColour> exr_colour;         // the scene's space, written into every EXR
    std::optional<OutputStaging> staging;        // made by the first file written
    std::vector<std::filesystem::path> written;  // final paths (output_dir / name), valid after commit_outputs()
    ExrMetadata exr_metadata = {};               // the spheres (render/exr_metadata.hpp), written into every EXR
    double exposure = 1.0;                       // PNGs' radiance scale (2^EV); EXRs are written as rendered
    // The exact reference curve of each sphere's material (the fit-error frame's Fresnel), and the luminance weights
    // of the scene's space (the error views).
    std::vector<const SphereFresnel*> reference_fresnel = {};
    RGB luminance{0, 0, 0};
    // What the renderer is made for; unset: plan_features(scene) (the sheet's columns add their glossy methods).
    std::optional<Features> features = {};
    // The scene's space for ΔE2000 (metrics.json, delta-e.png): its RGB → XYZ and the white Y_w = 1.
    DeltaEBasis delta_e = {};
    // max_bounces > 1: each sphere's exact spectral Fresnel and the RGB → spectrum uplift of the spectral reference
    // (render/bounce_orders.hpp); reference_fresnel is then set too.
    std::vector<std::shared_ptr<const SpectralFresnel>> spectral = {};
    std::shared_ptr<const RgbUplift> uplift = {};

    void open_gl();  // the context (if none) and the renderer; called before the first GPU pass
    GpuRenderer& renderer();
    // Where a pass writes the output file `name` (staged; the display transform is made with the first file) and
    // records output_dir / name as written.
    std::filesystem::path output_file(const std::string& name);
    // After the graph ran: every staged file into output_dir as one unit (nothing there changes when one failed).
    void commit_outputs();
};

// Scene inputs every preview graph imports.
struct SceneInputs {
    graph::Handle<const Scene*> environment, materials, camera;
};
SceneInputs import_scene(graph::PassGraph& graph, const Scene& scene);

// The environment a GPU frame reads: the cube captured from a procedural room or an equirect on its proxy, and/or
// the equirect texture of an image (with its CPU image for the reference tracer).
struct EnvironmentInputs {
    std::optional<graph::Handle<EnvironmentCube>> cube;
    std::optional<graph::Handle<EquirectTexture>> equirect_texture;
    std::optional<graph::Handle<Image>> equirect_image;

    void declare(graph::Builder& b) const;                   // the frame pass reads what exists
    void bind(GpuRenderer& gpu, graph::Resources& r) const;  // and hands it to the renderer
};
// The environment passes the features call for (capture-environment or load-equirect) and the skips --explain lists.
// `capture_inputs`: what the capture reads besides the scene (the lights' shadow maps), declared and bound by it.
EnvironmentInputs add_environment_passes(graph::PassGraph& graph, const Scene& scene, const Features& features,
                                         const SceneInputs& in, PreviewRun* run,
                                         const FrameInputs* capture_inputs = nullptr);

// The CPU images and values a preview produces (handles into the graph; a culled writer leaves them empty).
struct PreviewHandles {
    EnvironmentInputs environment;
    std::optional<graph::Handle<FresnelSet>> luts, parameters;
    graph::Handle<Image> beauty;
    graph::Handle<ReferenceRender> reference;  // the Monte-Carlo one when a sphere is rough, else the analytic one
    std::optional<graph::Handle<Image>> reference_standard_error;  // per pixel, when a sphere is rough
    graph::Handle<Image> difference;
    // The beauty frame with every sphere's Fresnel the exact reference curve (same localization and lobes): the model
    // spheres' fit error alone is beauty − this. Only when some sphere uses a model and difference or metrics is asked.
    std::optional<graph::Handle<Image>> fit_reference;
    graph::Handle<Image> localization;  // r: steps taken, g: |ρ − 1|, b: 1 on impostor spheres
    graph::Handle<FrameTimes> frame_times;
    graph::Handle<Json> metrics;
    // max_bounces > 1: per sphere, the errors of each bounce order (render/bounce_orders.hpp), metrics.json's
    // "bounce_orders" of each sphere.
    std::optional<graph::Handle<Json>> bounce_orders = {};
    // Figures an effect adds to metrics.json, each under its own key (its output passes run before the metrics').
    std::vector<std::pair<std::string, graph::Handle<Json>>> effect_metrics = {};
    // The room's light maps effects made for the frame, by their name (render/room_light_maps.hpp): what their own
    // output passes measure.
    std::map<std::string, graph::Handle<RoomLightMaps>> room_light_maps = {};
};

// Every pass of a preview and the skips --explain lists. `run` may be null (compile and explain only).
PreviewHandles add_preview_passes(graph::PassGraph& graph, const Scene& scene, const Features& features,
                                  PreviewRun* run);
// The effects no scene needs yet, listed after the culled passes.
void skip_unneeded_effects(graph::PassGraph& graph);

// One pass each (preview_passes.cpp).
// `equirect`: the image an equirect on its proxy paints on the proxy (the capture reads it).
graph::Handle<EnvironmentCube> add_capture_environment_pass(graph::PassGraph&, const Scene&, const Features&,
                                                            const SceneInputs&, PreviewRun*,
                                                            std::optional<graph::Handle<EquirectTexture>> equirect = {},
                                                            const FrameInputs* capture_inputs = nullptr);
std::pair<graph::Handle<EquirectTexture>, graph::Handle<Image>> add_load_equirect_pass(graph::PassGraph&, const Scene&,
                                                                                       PreviewRun*);
graph::Handle<FresnelSet> add_reference_luts_pass(graph::PassGraph&, const Scene&, const SceneInputs&, PreviewRun*);
graph::Handle<FresnelSet> add_model_parameters_pass(graph::PassGraph&, const Features&, const SceneInputs&,
                                                    PreviewRun*);
// A PNG gets the run's exposure unless the pass that made the image applied it (a sheet whose labels and error
// views are drawn after the exposure, so that they look the same at every exposure).
enum class PngExposure { apply, already_applied };
// `caption` (a PNG's, when not empty): what the image shows, drawn in its top band with the display transform and
// the exposure after it ("beauty: GPU preview; sRGB - Display / Un-tone-mapped, exposure +0 EV").
void add_image_file_pass(graph::PassGraph&, const std::string& file, graph::Handle<Image> image, PreviewRun*,
                         PngExposure = PngExposure::apply, const std::string& caption = {});
// The run's exposure on a copy of `image` (the PNG's radiance).
Image exposed(const Image& image, double exposure);
void add_image_file_pass(graph::PassGraph&, const std::string& file, graph::Handle<ReferenceRender> image, PreviewRun*,
                         const std::string& caption = {});
// The height of the caption's band in an image of `height` rows.
int caption_band_height(int height);
void add_json_file_pass(graph::PassGraph&, const std::string& file, const std::string& why, graph::Handle<Json> json,
                        PreviewRun*);

}  // namespace metalfit::glpreview
