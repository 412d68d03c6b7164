// The glossy benchmark as passes (issue 17 item 4): the sphere's Fresnel, one Monte-Carlo reference per roughness,
// then the GPU: one renderer per cube format the methods need (as a preview of that one sphere would capture it),
// every variant's error against its reference and the interleaved timing of all variants against the mirror
// classic pass; the shipped mirror scenes' ms per frame; then the record.
#include <functional>
#include <map>
#include <memory>
#include <string>
#include <vector>

#include "frame_timing.hpp"
#include "glpreview/render/environment.hpp"
#include "glpreview/render/gpu_renderer.hpp"
#include "glpreview/render/monte_carlo_reference.hpp"
#include "glpreview/render/scene_colour.hpp"
#include "glpreview/render/sphere_metrics.hpp"
#include "gpu_bench_passes.hpp"

namespace metalfit::glpreview {
namespace {

using graph::Builder;
using graph::Handle;
using graph::PassGraph;
using graph::Processor;
using graph::Resources;
using Json = nlohmann::ordered_json;
using BenchFresnel = const SphereFresnel*;
// By roughness, as glossy_bench_roughness(), then the analytic one of the mirror; each with its noise (0 for the mirror).
struct References {
    std::vector<ReferenceRender> images;
    std::vector<double> noise;
};

// The cube formats of the variants: what plan_features gives a scene of that one sphere.
enum class CubeGroup { mirror, prefiltered_box, prefiltered_impostor, localized };
CubeGroup group_of(const GlossyVariant& v) {
    if (v.roughness == 0) return CubeGroup::mirror;
    if (v.glossy == GlossyMethod::localized) return CubeGroup::localized;
    return v.reflection == ReflectionMode::box_parallax ? CubeGroup::prefiltered_box : CubeGroup::prefiltered_impostor;
}

void apply(Sphere& sphere, const GlossyVariant& v) {
    sphere.roughness = v.roughness;
    sphere.glossy = v.glossy;
    sphere.reflection = v.reflection;
    sphere.localized_size = v.localized_size;
}

// The renderers of one run: one per cube group, each with its scene (whose one sphere changes between frames).
struct GlossyRenderers {
    std::vector<std::unique_ptr<Scene>> scenes;
    std::vector<std::unique_ptr<GpuRenderer>> renderers;
    std::map<CubeGroup, std::size_t> by_group;
};

GlossyRenderers make_renderers(const Scene& base, const SphereFresnel* fresnel) {
    GlossyRenderers out;
    std::map<CubeGroup, std::vector<GlossyVariant>> groups;
    for (const GlossyVariant& v : glossy_bench_variants()) groups[group_of(v)].push_back(v);
    for (const auto& [group, variants] : groups) {
        auto scene = std::make_unique<Scene>(base);
        apply(scene->spheres.at(0), variants.front());
        Features features = plan_features(*scene);
        for (const GlossyVariant& v : variants)
            if (v.glossy == GlossyMethod::localized && v.roughness > 0)
                features.downsample_sizes.insert(v.localized_size);
        auto gpu = std::make_unique<GpuRenderer>(*scene, features, std::vector<const SphereFresnel*>{fresnel}, nullptr);
        gpu->capture_environment();  // its own cube, prefiltered / downsampled as the features ask
        out.by_group[group] = out.renderers.size();
        out.scenes.push_back(std::move(scene));
        out.renderers.push_back(std::move(gpu));
    }
    return out;
}

Json time_variants(const Scene& base, const SphereFresnel* fresnel, const References& references, int rounds) {
    GlossyRenderers r = make_renderers(base, fresnel);
    const std::vector<GlossyVariant> variants = glossy_bench_variants();
    const std::vector<double> roughness = glossy_bench_roughness();
    std::vector<std::function<void()>> frames;
    std::vector<SphereError> errors;
    std::vector<double> noise;
    for (const GlossyVariant& v : variants) {
        const std::size_t k = r.by_group.at(group_of(v));
        Scene& scene = *r.scenes[k];
        GpuRenderer& gpu = *r.renderers[k];
        apply(scene.spheres.at(0), v);
        std::size_t level = 0;
        while (level < roughness.size() && roughness[level] != v.roughness) ++level;
        // The mirror baseline is measured against the analytic reference (kept last).
        const std::size_t which = v.roughness == 0 ? references.images.size() - 1 : level;
        errors.push_back(sphere_errors(gpu.render(), references.images.at(which), 1).front());
        noise.push_back(references.noise.at(which));
        frames.push_back([&scene, &gpu, v] {
            apply(scene.spheres.at(0), v);
            gpu.draw_frame_for_timing();
        });
    }
    const RoundTimes ms = interleaved_rounds(frames, rounds);
    Json rows = Json::array();
    for (std::size_t i = 0; i < variants.size(); ++i) {
        const GlossyVariant& v = variants[i];
        const Ratio ratio = paired_ratio(ms[i], ms[0]);
        rows.push_back(
            {{"roughness", v.roughness},
             {"method", glossy_variant_name(v)},
             {"glossy", v.roughness > 0 ? Json(to_string(v.glossy)) : Json()},
             {"reflection",
              v.glossy == GlossyMethod::localized && v.roughness > 0 ? Json() : Json(to_string(v.reflection))},
             {"localized_size",
              v.glossy == GlossyMethod::localized && v.roughness > 0 ? Json(v.localized_size) : Json()},
             {"ms_per_frame", median(ms[i])},
             {"ratio_to_mirror_classic", ratio.median},
             {"ratio_noise", ratio.noise},
             {"rmse", errors[i].rmse},
             {"mean_abs", errors[i].mean_abs},
             {"reference_noise", noise[i]}});
    }
    return rows;
}

// The shipped scenes whose spheres are all mirrors, at their own size (quick: 128 × 96), `frames` frames each.
Json time_mirror_scenes(const GpuBenchRun& run, int frames) {
    Json out = Json::array();
    for (const char* name :
         {"empty-room.json", "difficult-room.json", "occluder-maze.json", "sheet.json", "sky.json"}) {
        Scene scene = load_scene(run.options.data_dir / "scenes" / name);
        if (run.quick) {
            scene.width = 128;
            scene.height = 96;
        }
        FresnelLibrary library(run.options.data_dir, run.options.ocio, scene.space, scene.file, scene.paths);
        std::vector<const SphereFresnel*> fresnel;
        for (std::size_t i = 0; i < scene.spheres.size(); ++i)
            fresnel.push_back(&library.get(scene.spheres[i], "spheres[" + std::to_string(i) + "]"));
        std::optional<Image> equirect;
        if (scene.environment.type == EnvironmentType::equirect)
            equirect = read_environment_image(scene, run.options.ocio);
        GpuRenderer gpu(scene, plan_features(scene), fresnel, equirect ? &*equirect : nullptr);
        gpu.capture_environment();
        const std::vector<double> ms = gpu.time_frames(frames);
        out.push_back({{"scene", name},
                       {"size", {scene.width, scene.height}},
                       {"spheres", scene.spheres.size()},
                       {"ms_per_frame", median(ms)}});
    }
    return out;
}

}  // namespace

std::vector<double> glossy_bench_roughness() { return {0.05, 0.1, 0.2, 0.4, 0.8}; }

std::vector<GlossyVariant> glossy_bench_variants() {
    std::vector<GlossyVariant> variants{
        {0, GlossyMethod::prefiltered, ReflectionMode::classic, 8}};  // the mirror classic pass
    for (double r : glossy_bench_roughness()) {
        variants.push_back({r, GlossyMethod::prefiltered, ReflectionMode::box_parallax, 8});
        variants.push_back({r, GlossyMethod::prefiltered, ReflectionMode::distance_impostor, 8});
        for (int m : {2, 4, 8}) variants.push_back({r, GlossyMethod::localized, ReflectionMode::distance_impostor, m});
    }
    return variants;
}

std::string glossy_variant_name(const GlossyVariant& v) {
    if (v.roughness == 0) return std::string("mirror ") + to_string(v.reflection);
    if (v.glossy == GlossyMethod::localized) return "localized M=" + std::to_string(v.localized_size);
    return std::string("prefiltered ") + to_string(v.reflection);
}

Scene glossy_bench_scene(const std::filesystem::path& data_dir, bool quick, const GlossyVariant& variant) {
    Scene scene =
        localization_rooms(data_dir, true).back().scene;  // the difficult room, the camera close to the sphere
    scene.width = scene.height = quick ? 48 : 128;
    scene.outputs.reference_samples = quick ? 32 : 256;
    scene.outputs.timing_frames = 5;
    Sphere& sphere = scene.spheres.at(0);
    sphere.fresnel = ReferenceFresnel{};
    sphere.strategy = kDefaultStrategy;
    sphere.iterations = kDefaultIterations;
    sphere.tolerance = kDefaultTolerance;
    apply(sphere, variant);
    return scene;
}

Handle<Json> add_glossy_cost_passes(PassGraph& graph, GpuBenchRun& run) {
    const int rounds = run.quick ? 3 : 9;
    const Scene base = glossy_bench_scene(run.options.data_dir, run.quick, glossy_bench_variants().front());
    const Handle<BenchFresnel> fresnel =
        add_bench_fresnel_pass(graph, "glossy-fresnel", "the bench sphere: its reference R_c(μ) from libfit", run,
                               run.glossy_library, [base]() -> const Scene& { return base; });
    struct ReferenceData {
        Handle<References> out;
    };
    const Handle<References> references =
        graph
            .add_pass<ReferenceData>(
                {"glossy-references",
                 "per roughness of the table: the Monte-Carlo reference (" +
                     std::to_string(base.outputs.reference_samples) +
                     " samples per pixel, as a preview's), and the analytic one for the mirror",
                 Processor::cpu},
                [&](Builder& b, ReferenceData& d) {
                    b.read(fresnel);
                    d.out = b.produce<References>("glossy-reference-images");
                },
                [&run, base, fresnel](const ReferenceData& d, Resources& r) {
                    References& out = r.emplace(d.out);
                    const EnvironmentTracer tracer(base.environment);
                    const std::vector<const SphereFresnel*> f{r.get(fresnel)};
                    for (double roughness : glossy_bench_roughness()) {
                        Scene scene = base;
                        scene.spheres.at(0).roughness = roughness;
                        const ReferenceRender analytic = render_reference(scene, f, tracer, run.options.threads);
                        MonteCarloReference mc = render_monte_carlo_reference(
                            scene, f, tracer, analytic, scene.outputs.reference_samples, run.options.threads);
                        out.noise.push_back(sphere_reference_noise(mc.standard_error, mc.render, 1).front());
                        out.images.push_back(std::move(mc.render));
                    }
                    out.images.push_back(render_reference(base, f, tracer, run.options.threads));
                    out.noise.push_back(0);
                })
            .out;
    struct Timing {
        Handle<Json> rows, mirror_scenes;
    };
    const Timing& timing = graph.add_pass<Timing>(
        {"glossy-timing",
         std::to_string(glossy_bench_variants().size()) +
             " variants (the mirror classic pass, then roughness × method): error of one frame, then " +
             std::to_string(rounds) + " interleaved rounds; the shipped mirror scenes' ms per frame",
         Processor::gpu},
        [&](Builder& b, Timing& d) {
            b.read(fresnel);
            b.read(references);
            d.rows = b.produce<Json>("glossy-rows");
            d.mirror_scenes = b.produce<Json>("mirror-scene-times");
        },
        [&run, base, fresnel, references, rounds](const Timing& d, Resources& r) {
            r.emplace(d.rows, time_variants(base, r.get(fresnel), r.get(references), rounds));
            r.emplace(d.mirror_scenes, time_mirror_scenes(run, run.quick ? 5 : 9));
        });
    struct Record {
        Handle<Json> out;
    };
    return graph
        .add_pass<Record>(
            {"glossy-record",
             "roughness × method: median ms per frame, paired ratio to the mirror classic pass, RMSE against the Monte-Carlo reference",
             Processor::cpu},
            [&](Builder& b, Record& d) {
                b.read(timing.rows);
                b.read(timing.mirror_scenes);
                d.out = b.produce<Json>("glossy-bench");
            },
            [&run, base, timing, rounds](const Record& d, Resources& r) {
                Json& j = r.emplace(d.out);
                j["renderer"] = run.context->renderer();
                j["size"] = {base.width, base.height};
                j["frames"] = rounds;
                j["clock"] = frame_timer_name(frame_timer());
                j["reference_samples"] = base.outputs.reference_samples;
                j["material"] = base.spheres.at(0).material;
                j["rows"] = r.get(timing.rows);
                j["mirror_scenes"] = r.get(timing.mirror_scenes);
            })
        .out;
}

}  // namespace metalfit::glpreview
