// The localization benchmark as passes: the reference Fresnel of the rooms' sphere, then per room the CPU reference,
// the cube capture (into a cube the graph creates with a distance channel) and the interleaved timing of every
// reflection mode and iteration count with its error against the reference; then the record.
#include <functional>
#include <string>
#include <vector>

#include "frame_timing.hpp"
#include "glpreview/render/environment.hpp"
#include "glpreview/render/gpu_renderer.hpp"
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

struct Row {
    ReflectionMode mode;
    Strategy strategy;
    int iterations;
    int search_steps = 0;  // the safeguarded strategies' linear search (0: none)
};

std::vector<Row> localization_rows() {
    std::vector<Row> rows{{ReflectionMode::classic, Strategy::secant, 0},
                          {ReflectionMode::box_parallax, Strategy::secant, 0}};
    for (Strategy s :
         {Strategy::secant, Strategy::false_position, Strategy::mixed, Strategy::illinois, Strategy::safe_secant})
        for (int n : {0, 1, 2, 4, 8, 16}) {
            const bool searches = s == Strategy::illinois || s == Strategy::safe_secant;
            rows.push_back({ReflectionMode::distance_impostor, s, n, searches ? kDefaultSearchSteps : 0});
        }
    // The default's linear search against none and a finer one (docs/preview.md, "The right root").
    for (int search : {0, 4, 16, 32})
        rows.push_back({ReflectionMode::distance_impostor, kDefaultStrategy, kDefaultIterations, search});
    return rows;
}

void apply(Sphere& sphere, const Row& row) {
    sphere.tolerance = kDefaultTolerance;
    sphere.reflection = row.mode;
    sphere.strategy = row.strategy;
    sphere.iterations = row.iterations;
    sphere.search_steps = row.search_steps;
}

using BenchFresnel = const SphereFresnel*;

// Per row: the error of one frame against the CPU reference, then `rounds` interleaved timed frames.
Json time_rows(Scene& scene, GpuRenderer& gpu, const ReferenceRender& reference, int rounds) {
    Sphere& sphere = scene.spheres.at(0);
    const std::vector<Row> rows = localization_rows();
    std::vector<std::function<void()>> variants;
    std::vector<SphereError> errors;
    std::vector<SphereLocalization> effort;
    for (const Row& row : rows) {
        apply(sphere, row);
        errors.push_back(sphere_errors(gpu.render(), reference, 1).front());
        effort.push_back(sphere_localization(gpu.render_localization(), reference, 1).front());
        variants.push_back([&, row] {
            apply(sphere, row);
            gpu.draw_frame_for_timing();
        });
    }
    const RoundTimes ms = interleaved_rounds(variants, rounds);
    Json out = Json::array();
    for (std::size_t i = 0; i < rows.size(); ++i) {
        const bool impostor = rows[i].mode == ReflectionMode::distance_impostor;
        const Ratio ratio = paired_ratio(ms[i], ms[0]);
        out.push_back({{"mode", to_string(rows[i].mode)},
                       {"strategy", impostor ? Json(to_string(rows[i].strategy)) : Json()},
                       {"iterations", impostor ? rows[i].iterations : 0},
                       {"search_steps", rows[i].search_steps},
                       {"tolerance", impostor ? Json(sphere.tolerance) : Json()},
                       {"mean_iterations", impostor ? effort[i].mean_iterations : 0.0},
                       {"ms_per_frame", median(ms[i])},
                       {"ratio_to_classic", ratio.median},
                       {"ratio_noise", ratio.noise},
                       {"rmse", errors[i].rmse},
                       {"mean_abs", errors[i].mean_abs}});
    }
    return out;
}

}  // namespace

std::vector<LocalizationRoom> localization_rooms(const std::filesystem::path& data_dir, bool quick) {
    Scene difficult = load_scene(data_dir / "scenes" / "sheet.json");
    difficult.width = quick ? 256 : 512;
    difficult.height = quick ? 256 : 512;
    // The camera close to the sphere, so that the reflection (not the background) fills most of the frame.
    const Sphere& subject = difficult.spheres.at(0);
    difficult.camera.look_at = subject.center;
    difficult.camera.position = subject.center + Vec3{0, 0.15, 0.95};
    difficult.camera.fov_y_deg = 70;
    Scene empty = difficult;
    empty.environment.room.boxes.clear();
    std::vector<LocalizationRoom> rooms{{"empty", std::move(empty)}, {"difficult", std::move(difficult)}};
    for (LocalizationRoom& room : rooms) {
        Sphere& sphere = room.scene.spheres.at(0);
        sphere.fresnel = ReferenceFresnel{};
        sphere.reflection = ReflectionMode::distance_impostor;  // the renderer's cube stores distances
    }
    return rooms;
}

Handle<Json> add_localization_cost_passes(PassGraph& graph, GpuBenchRun& run) {
    const int rounds = run.quick ? 3 : 7;
    const Handle<BenchFresnel> fresnel =
        add_bench_fresnel_pass(graph, "bench-fresnel", "the rooms' sphere: its reference R_c(μ) LUT from libfit", run,
                               run.library, [&run]() -> const Scene& { return run.rooms.front().scene; });

    std::vector<Handle<Json>> room_rows;
    for (LocalizationRoom& room : run.rooms) {
        struct Reference {
            Handle<ReferenceRender> out;
        };
        const Handle<ReferenceRender> reference =
            graph
                .add_pass<Reference>(
                    {"cpu-reference " + room.name, "the ground truth of the " + room.name + " room's sphere",
                     Processor::cpu},
                    [&](Builder& b, Reference& d) {
                        b.read(fresnel);
                        d.out = b.produce<ReferenceRender>("reference-image " + room.name);
                    },
                    [&run, &room, fresnel](const Reference& d, Resources& r) {
                        const EnvironmentTracer tracer(room.scene.environment);
                        r.emplace(d.out, render_reference(room.scene, {r.get(fresnel)}, tracer, run.options.threads));
                    })
                .out;
        struct Capture {
            Handle<EnvironmentCube> cube;
            Handle<GpuRenderer> renderer;
        };
        const Capture& capture = graph.add_pass<Capture>(
            {"capture-environment " + room.name,
             "the " + room.name + " room into a " + std::to_string(room.scene.environment.cube_size) +
                 "² cube map (radiance + distance)",
             Processor::gpu},
            [&](Builder& b, Capture& d) {
                b.read(fresnel);
                d.cube = b.create<EnvironmentCube>("environment-cube " + room.name,
                                                   {room.scene.environment.cube_size, true});
                d.renderer = b.produce<GpuRenderer>("renderer " + room.name);
            },
            [&room, fresnel](const Capture& d, Resources& r) {
                GpuRenderer& gpu = r.emplace(d.renderer, room.scene, plan_features(room.scene),
                                             std::vector<const SphereFresnel*>{r.get(fresnel)}, nullptr);
                gpu.capture_environment(r.get(d.cube));
            });
        struct Timing {
            Handle<Json> out;
        };
        room_rows.push_back(
            graph
                .add_pass<Timing>(
                    {"localization-timing " + room.name,
                     std::to_string(localization_rows().size()) + " reflection variants: error of one frame, then " +
                         std::to_string(rounds) + " interleaved rounds",
                     Processor::gpu},
                    [&](Builder& b, Timing& d) {
                        b.read(capture.cube);
                        b.read(capture.renderer);
                        b.read(reference);
                        d.out = b.produce<Json>("localization-rows " + room.name);
                    },
                    [&room, capture, reference, rounds](const Timing& d, Resources& r) {
                        r.get(capture.cube);  // bound to the renderer by its capture
                        r.emplace(d.out, time_rows(room.scene, r.get(capture.renderer), r.get(reference), rounds));
                    })
                .out);
    }

    struct Record {
        Handle<Json> out;
    };
    return graph
        .add_pass<Record>(
            {"localization-record",
             "per room and variant: median ms per frame, paired ratio to classic with its noise, RMSE, mean steps taken",
             Processor::cpu},
            [&](Builder& b, Record& d) {
                for (const Handle<Json>& rows : room_rows) b.read(rows);
                d.out = b.produce<Json>("localization-bench");
            },
            [&run, room_rows, rounds](const Record& d, Resources& r) {
                const Scene& scene = run.rooms.front().scene;
                Json& j = r.emplace(d.out);
                j["renderer"] = run.context->renderer();
                j["size"] = {scene.width, scene.height};
                j["frames"] = rounds;
                j["clock"] = frame_timer_name(frame_timer());
                j["rooms"] = Json::array();
                for (std::size_t i = 0; i < run.rooms.size(); ++i)
                    j["rooms"].push_back({{"room", run.rooms[i].name}, {"rows", r.get(room_rows[i])}});
            })
        .out;
}

}  // namespace metalfit::glpreview
