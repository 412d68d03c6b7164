#include "glpreview/render/preview_passes.hpp"

#include "glpreview/effects/registry.hpp"
#include "glpreview/render/frame_inputs.hpp"
#include "glpreview/render/environment.hpp"
#include "glpreview/render/exr_metadata.hpp"
#include "glpreview/render/monte_carlo_reference.hpp"
#include "glpreview/render/scene_colour.hpp"
#include "glpreview/render/sphere_metrics.hpp"
#include "libfit/base/atomic_file.hpp"
#include "libfit/base/errors.hpp"
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

template <typename T>
void add_image_file(PassGraph& graph, const std::string& file, Handle<T> image, PreviewRun* run) {
    const bool png = std::filesystem::path(file).extension() == ".png";
    graph.add_pass<Empty>(
        {"write " + file, png ? "through the OCIO display transform" : "linear half-float EXR", Processor::cpu},
        [&](Builder& b, Empty&) {
            b.read(image);
            b.write_file(file);
        },
        [run, file, image, png](const Empty&, Resources& r) {
            if (run->output_dir.empty()) return;
            const std::filesystem::path path = run->output_file(file);
            if (png) write_png(path, image_of(r.get(image)), *run->display);
            else write_exr(path, image_of(r.get(image)), run->exr_colour ? &*run->exr_colour : nullptr,
                           image_metadata(run->exr_metadata, file));
        });
}

// The frame times: apart from metrics.json, which is then the same bytes on every run of the same scene.
Json timings_json(const PreviewRun& run, const FrameTimes& frame_ms) {
    Json j;
    j["schema"] = "metalfit.preview-timings/1";
    j["scene"] = run.scene.file.filename().string();
    j["renderer"] = run.renderer_name;
    j["size"] = {run.scene.width, run.scene.height};
    j["ms_per_frame"] = frame_ms.empty() ? 0.0 : median(frame_ms);
    j["frame_ms"] = frame_ms;
    return j;
}

Json metrics_json(const PreviewRun& run, const Image& beauty, const ReferenceRender& reference, const Image& localization,
                  const Image* standard_error) {
    const Scene& scene = run.scene;
    Json j;
    j["schema"] = "metalfit.preview-metrics/1";
    j["scene"] = scene.file.filename().string();
    j["renderer"] = run.renderer_name;
    j["size"] = {scene.width, scene.height};
    j["space"] = scene.space.empty() ? std::string("scene_linear") : scene.space;  // as the scene names it
    const auto errors = sphere_errors(beauty, reference, scene.spheres.size());
    const auto effort = sphere_localization(localization, reference, scene.spheres.size());
    const auto noise = standard_error ? sphere_reference_noise(*standard_error, reference, scene.spheres.size())
                                      : std::vector<double>(scene.spheres.size(), 0.0);
    j["spheres"] = Json::array();
    for (std::size_t i = 0; i < scene.spheres.size(); ++i) {
        const Sphere& s = scene.spheres[i];
        // A localized rough sphere looks nothing up along its reflection mode: no impostor statistics.
        const bool impostor = s.reflection == ReflectionMode::distance_impostor && !(s.rough() && s.glossy == GlossyMethod::localized);
        Json e;
        e["sphere"] = i;
        e["material"] = run.fresnel[i]->material;
        e["source"] = run.fresnel[i]->source;
        e["fresnel"] = fresnel_name(s.fresnel);
        const auto* model = std::get_if<ModelFresnel>(&s.fresnel);
        e["params"] = model ? Json(to_string(model->parameters)) : Json(nullptr);
        e["mode"] = to_string(s.reflection);
        e["strategy"] = impostor ? Json(to_string(s.strategy)) : Json(nullptr);
        e["iterations"] = impostor ? s.iterations : 0;
        e["tolerance"] = impostor ? Json(s.tolerance) : Json(nullptr);
        e["rmse"] = errors[i].rmse;  // NaN (null) when no pixel shows the sphere
        e["mean_abs"] = errors[i].mean_abs;
        e["pixels"] = errors[i].pixels;
        e["mean_iterations"] = impostor ? Json(effort[i].mean_iterations) : Json(nullptr);
        e["mean_rho_error"] = impostor ? Json(effort[i].mean_rho_error) : Json(nullptr);
        e["roughness"] = s.roughness;
        e["glossy"] = s.rough() ? Json(to_string(s.glossy)) : Json(nullptr);
        e["localized_size"] = s.rough() && s.glossy == GlossyMethod::localized ? Json(s.localized_size) : Json(nullptr);
        e["reference_noise"] = s.rough() ? noise[i] : 0.0;  // NaN (null) when no pixel shows the sphere
        j["spheres"].push_back(e);
    }
    return j;
}

// The inputs of a GPU frame (beauty, localization, timing) bound to the renderer: the environment, the Fresnel
// data (so that the frames run after the passes that resolve it) and what the effects hand to the frame.
struct FrameBinding {
    EnvironmentInputs environment;
    std::optional<Handle<FresnelSet>> luts, parameters;
    FrameInputs effects;

    void declare(Builder& b, Handle<const Scene*> camera) const {
        b.read(camera);
        environment.declare(b);
        if (luts) b.read(*luts);
        if (parameters) b.read(*parameters);
        effects.declare(b);
    }
    GpuRenderer& bind(PreviewRun& run, Resources& r) const {
        GpuRenderer& gpu = run.renderer();
        environment.bind(gpu, r);
        effects.bind(gpu.frame(), r);
        return gpu;
    }
};

}  // namespace

void PreviewRun::open_gl() {
    if (gpu) return;
    if (!context) context = &own_context.emplace(GlContext::create());
    renderer_name = context->renderer();
    gpu.emplace(scene, plan_features(scene), fresnel, nullptr, &context->programs());
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
    if (!display && std::filesystem::path(name).extension() == ".png") display = DisplayTransform::create(ocio, scene.space);
    written.push_back(output_dir / name);
    return staging->file(name);
}

void PreviewRun::commit_outputs() {
    if (staging) staging->commit();
}

SceneInputs import_scene(PassGraph& graph, const Scene& scene) {
    return {graph.import<const Scene*>("environment-description", &scene), graph.import<const Scene*>("materials", &scene),
            graph.import<const Scene*>("camera", &scene)};
}

namespace {
// What the capture ray-casts: "procedural room", or "equirect on its box proxy".
std::string captured_environment_name(const Environment& environment) {
    if (environment.type != EnvironmentType::equirect) return std::string("procedural ") + to_string(environment.type);
    if (const auto* sphere = std::get_if<SphereProxy>(&*environment.equirect.proxy))
        return "equirect on its sphere proxy (radius " + glsl_float(sphere->radius) + ")";
    return "equirect on its box proxy";
}
}  // namespace

Handle<EnvironmentCube> add_capture_environment_pass(PassGraph& graph, const Scene& scene, const Features& f,
                                                     const SceneInputs& in, PreviewRun* run,
                                                     std::optional<Handle<EquirectTexture>> equirect) {
    struct Data {
        std::optional<Handle<EquirectTexture>> equirect;
        Handle<EnvironmentCube> out;
    };
    return graph
        .add_pass<Data>(
            {"capture-environment",
             captured_environment_name(scene.environment) + ": ray-cast by GL into a " +
                 std::to_string(scene.environment.cube_size) + "² cube map (radiance" + (f.distance_channel ? " + distance" : "") +
                 ")" + (f.prefiltered_map ? " with a mip chain for the prefilter" : "") + ", once, reused by every frame",
             Processor::gpu},
            [&](Builder& b, Data& d) {
                b.read(in.environment);
                if (equirect) d.equirect = b.read(*equirect);
                d.out = b.create<EnvironmentCube>("environment-cube", {scene.environment.cube_size, f.distance_channel, f.prefiltered_map});
            },
            [run](const Data& d, Resources& r) {
                if (d.equirect) run->renderer().use_equirect(r.get(*d.equirect));
                run->renderer().capture_environment(r.get(d.out));
            })
        .out;
}

std::pair<Handle<EquirectTexture>, Handle<Image>> add_load_equirect_pass(PassGraph& graph, const Scene& scene, PreviewRun* run) {
    struct Data {
        Handle<EquirectTexture> texture;
        Handle<Image> image;
    };
    const Equirect& equirect = scene.environment.equirect;
    const Data& d = graph.add_pass<Data>(
        {"load-equirect",
         std::string(equirect.proxy ? "environment image on a proxy: " : "environment at infinity: ") + equirect.file.string() + " (OpenImageIO)" +
             (equirect.colorspace.empty() ? std::string(", taken as the scene's space (untagged)")
                                          : ", from " + equirect.colorspace + " into the scene's space"),
         Processor::cpu},
        [](Builder& b, Data& d) {
            d.texture = b.produce<EquirectTexture>("equirect-texture");
            d.image = b.produce<Image>("equirect-image");
        },
        [&scene, run](const Data& d, Resources& r) {
            const Image& image = r.emplace(d.image, read_environment_image(scene, run->ocio));
            r.emplace(d.texture, std::make_shared<const Image>(image));
        });
    return {d.texture, d.image};
}

void EnvironmentInputs::declare(Builder& b) const {
    if (cube) b.read(*cube);
    if (equirect_texture) b.read(*equirect_texture);
}

void EnvironmentInputs::bind(GpuRenderer& gpu, Resources& r) const {
    if (cube) gpu.use_environment(r.get(*cube));
    if (equirect_texture) gpu.use_equirect(r.get(*equirect_texture));
}

EnvironmentInputs add_environment_passes(PassGraph& graph, const Scene& scene, const Features& f, const SceneInputs& in,
                                         PreviewRun* run) {
    EnvironmentInputs environment;
    if (f.equirect_image) {
        const auto [texture, image] = add_load_equirect_pass(graph, scene, run);
        environment.equirect_texture = texture;
        environment.equirect_image = image;
    }
    if (f.environment_capture) {
        environment.cube = add_capture_environment_pass(graph, scene, f, in, run, environment.equirect_texture);
        if (!f.distance_channel)
            graph.skip("distance channel", "no sphere uses the distance impostor: the cube map stores radiance only (RGBA16F)");
    } else {
        graph.skip("capture-environment", "the environment is an image at infinity: nothing to capture");
    }
    return environment;
}

Handle<FresnelSet> add_reference_luts_pass(PassGraph& graph, const Scene& scene, const SceneInputs& in, PreviewRun* run) {
    return graph
        .add_pass<Out<FresnelSet>>(
            {"reference-luts", "some sphere shows the exact reference: R_c(μ) from libfit into 1D RGB textures (256 texels)",
             Processor::cpu},
            [&](Builder& b, Out<FresnelSet>& d) {
                b.read(in.materials);
                d.out = b.produce<FresnelSet>("fresnel-luts");
            },
            [run, &scene](const Out<FresnelSet>& d, Resources& r) {
                FresnelSet& set = r.emplace(d.out);
                for (std::size_t i = 0; i < scene.spheres.size(); ++i)
                    set.spheres.push_back(run->fresnel[i]->model ? nullptr : run->fresnel[i]);
            })
        .out;
}

Handle<FresnelSet> add_model_parameters_pass(PassGraph& graph, const Features& f, const SceneInputs& in, PreviewRun* run) {
    return graph
        .add_pass<Out<FresnelSet>>(
            {"model-parameters", "models " + join({f.models.begin(), f.models.end()}) + ": parameters from libfit (Ceres fit or closed form)",
             Processor::cpu},
            [&](Builder& b, Out<FresnelSet>& d) {
                b.read(in.materials);
                d.out = b.produce<FresnelSet>("model-parameters");
            },
            [run](const Out<FresnelSet>& d, Resources& r) {
                FresnelSet& set = r.emplace(d.out);
                for (const SphereFresnel* fresnel : run->fresnel) set.spheres.push_back(fresnel->model ? fresnel : nullptr);
            })
        .out;
}

void add_image_file_pass(PassGraph& graph, const std::string& file, Handle<Image> image, PreviewRun* run) {
    add_image_file(graph, file, image, run);
}
void add_image_file_pass(PassGraph& graph, const std::string& file, Handle<ReferenceRender> image, PreviewRun* run) {
    add_image_file(graph, file, image, run);
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

void add_json_file_pass(PassGraph& graph, const std::string& file, const std::string& why, Handle<Json> json, PreviewRun* run) {
    add_json_file(graph, file, why, json, run, [](const Json& j) -> const Json& { return j; });
}

PreviewHandles add_preview_passes(PassGraph& graph, const Scene& scene, const Features& f, PreviewRun* run) {
    PreviewHandles h;
    const SceneInputs in = import_scene(graph, scene);
    FrameBinding frame;
    h.environment = frame.environment = add_environment_passes(graph, scene, f, in, run);
    if (f.reference_lut) h.luts = frame.luts = add_reference_luts_pass(graph, scene, in, run);
    else graph.skip("reference-luts", "no sphere uses fresnel 'reference'");
    if (f.model_fits) h.parameters = frame.parameters = add_model_parameters_pass(graph, f, in, run);
    else graph.skip("model-parameters", "no sphere uses a libfit model");
    // The effects' passes (effects/registry.hpp), and what each hands to the frames.
    PreviewGraph effects{graph, scene, f, in, h.environment.cube, run, frame.effects};
    for (const Effect* effect : all_effects()) effect->add_preview_passes(effects);

    // beauty: one frame of every sphere with its shader variant.
    h.beauty = graph
                   .add_pass<Out<Image>>(
                       {"beauty", std::to_string(f.shader_variants.size()) + " sphere shader variant(s): " +
                                      join({f.shader_variants.begin(), f.shader_variants.end()}, " | "),
                        Processor::gpu},
                       [&](Builder& b, Out<Image>& d) {
                           frame.declare(b, in.camera);
                           d.out = b.produce<Image>("beauty-image");
                       },
                       [run, frame](const Out<Image>& d, Resources& r) { r.emplace(d.out, frame.bind(*run, r).render()); })
                   .out;
    // cpu-reference: the ground truth.
    h.reference = graph
                      .add_pass<Out<ReferenceRender>>(
                          {"cpu-reference", "analytic ray tracing of the same scene: exact mirror reflections, same Fresnel, same camera",
                           Processor::cpu},
                          [&](Builder& b, Out<ReferenceRender>& d) {
                              b.read(in.camera);
                              if (h.environment.equirect_image) b.read(*h.environment.equirect_image);
                              if (h.luts) b.read(*h.luts);
                              if (h.parameters) b.read(*h.parameters);
                              d.out = b.produce<ReferenceRender>("reference-image");
                          },
                          [run, equirect = h.environment.equirect_image](const Out<ReferenceRender>& d, Resources& r) {
                              const EnvironmentTracer tracer(run->scene.environment, equirect ? &r.get(*equirect) : nullptr);
                              r.emplace(d.out, render_reference(run->scene, run->fresnel, tracer, run->threads));
                          })
                      .out;
    // monte-carlo-reference: the rough spheres' lobes by Monte Carlo, over the analytic reference's pixels.
    if (f.monte_carlo_reference) {
        struct Data {
            Handle<ReferenceRender> analytic, out;
            Handle<Image> standard_error;
        };
        std::vector<std::string> rough;
        for (std::size_t i = 0; i < scene.spheres.size(); ++i)
            if (scene.spheres[i].rough()) rough.push_back(std::to_string(i));
        const Data& mc = graph.add_pass<Data>(
            {"monte-carlo-reference",
             "sphere(s) " + join(rough) + " rough: the GGX lobe by Monte Carlo (" + std::to_string(scene.outputs.reference_samples) +
                 " visible-normal samples per pixel, fixed seed), exact reflected rays, same Fresnel; standard error beside it",
             Processor::cpu},
            [&](Builder& b, Data& d) {
                b.read(in.camera);
                if (h.environment.equirect_image) b.read(*h.environment.equirect_image);
                d.analytic = b.read(h.reference);
                d.out = b.produce<ReferenceRender>("monte-carlo-reference-image");
                d.standard_error = b.produce<Image>("reference-standard-error");
            },
            [run, equirect = h.environment.equirect_image](const Data& d, Resources& r) {
                const EnvironmentTracer tracer(run->scene.environment, equirect ? &r.get(*equirect) : nullptr);
                MonteCarloReference result = render_monte_carlo_reference(run->scene, run->fresnel, tracer, r.get(d.analytic),
                                                                          run->scene.outputs.reference_samples, run->threads);
                r.emplace(d.out, std::move(result.render));
                r.emplace(d.standard_error, std::move(result.standard_error));
            });
        h.reference = mc.out;
        h.reference_standard_error = mc.standard_error;
    } else {
        graph.skip("monte-carlo-reference", f.cpu_reference ? "every sphere is a mirror: the analytic reference is exact"
                                                            : "no reference, difference or metrics asked for");
    }
    // localization: the impostor's steps taken and final |ρ − 1| per pixel, one diagnostics frame.
    h.localization = graph
                         .add_pass<Out<Image>>(
                             {"localization", "per pixel: the impostor's refinement steps taken and |ρ − 1| at its lookup point",
                              Processor::gpu},
                             [&](Builder& b, Out<Image>& d) {
                                 frame.declare(b, in.camera);
                                 d.out = b.produce<Image>("localization-image");
                             },
                             [run, frame](const Out<Image>& d, Resources& r) {
                                 r.emplace(d.out, frame.bind(*run, r).render_localization());
                             })
                         .out;
    h.difference = graph
                       .add_pass<Out<Image>>(
                           {"difference", "|beauty − reference| per pixel", Processor::cpu},
                           [&](Builder& b, Out<Image>& d) {
                               b.read(h.beauty);
                               b.read(h.reference);
                               d.out = b.produce<Image>("difference-image");
                           },
                           [beauty = h.beauty, reference = h.reference](const Out<Image>& d, Resources& r) {
                               r.emplace(d.out, absolute_difference(r.get(beauty), r.get(reference).image));
                           })
                       .out;
    h.frame_times = graph
                        .add_pass<Out<FrameTimes>>(
                            {"timing", "ms per frame: median of " + std::to_string(scene.outputs.timing_frames) +
                                           " frames between glFinish calls",
                             Processor::gpu},
                            [&](Builder& b, Out<FrameTimes>& d) {
                                frame.declare(b, in.camera);
                                d.out = b.produce<FrameTimes>("frame-times");
                            },
                            [run, frame](const Out<FrameTimes>& d, Resources& r) {
                                r.emplace(d.out, frame.bind(*run, r).time_frames(run->scene.outputs.timing_frames));
                            })
                        .out;
    h.metrics = graph
                    .add_pass<Out<Json>>(
                        {"metrics", "per sphere: RMSE and mean |difference| of linear radiance inside the sphere mask", Processor::cpu},
                        [&](Builder& b, Out<Json>& d) {
                            b.read(h.beauty);
                            b.read(h.reference);
                            b.read(h.localization);
                            if (h.reference_standard_error) b.read(*h.reference_standard_error);
                            d.out = b.produce<Json>("metrics");
                        },
                        [run, h](const Out<Json>& d, Resources& r) {
                            r.emplace(d.out, metrics_json(*run, r.get(h.beauty), r.get(h.reference), r.get(h.localization),
                                                        h.reference_standard_error ? &r.get(*h.reference_standard_error) : nullptr));
                        })
                    .out;

    // Sinks: the files asked for, each bound to its writer.
    const Outputs& o = scene.outputs;
    std::vector<std::string> formats;
    if (o.exr) formats.push_back("exr");
    if (o.png) formats.push_back("png");
    for (const auto& format : formats)
        if (o.beauty) add_image_file_pass(graph, "beauty." + format, h.beauty, run);
    for (const auto& format : formats)
        if (o.reference) add_image_file_pass(graph, "reference." + format, h.reference, run);
    for (const auto& format : formats)
        if (o.difference) add_image_file_pass(graph, "difference." + format, h.difference, run);
    if (o.reference && h.reference_standard_error)
        add_image_file_pass(graph, "reference-stderr.exr", *h.reference_standard_error, run);
    if (o.localization) add_image_file_pass(graph, "localization.exr", h.localization, run);
    if (o.metrics) {
        add_json_file_pass(graph, "metrics.json", "asked for", h.metrics, run);
        add_json_file(graph, "timings.json", "asked for (metrics: the frame times, apart from metrics.json)", h.frame_times,
                      run, [run](const FrameTimes& frame_ms) { return timings_json(*run, frame_ms); });
    }
    return h;
}

void skip_unneeded_effects(PassGraph& graph) {
    graph.skip("SH irradiance", "metals have no diffuse lobe");
}

}  // namespace metalfit::glpreview
