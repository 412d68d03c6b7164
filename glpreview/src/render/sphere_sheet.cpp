#include "glpreview/render/sphere_sheet.hpp"

#include <cmath>
#include <optional>
#include <stdexcept>

#include "glpreview/render/gpu_renderer.hpp"
#include "glpreview/render/preview_passes.hpp"
#include "glpreview/render/sphere_fresnel.hpp"
#include "glpreview/render/sphere_metrics.hpp"
#include "libfit/base/errors.hpp"
#include "libfit/base/text.hpp"

namespace metalfit::glpreview {
namespace {

void paste(Image& sheet, const Image& cell, int column, int row) {
    for (int y = 0; y < cell.height; ++y)
        for (int x = 0; x < cell.width; ++x) sheet.set(column * cell.width + x, row * cell.height + y, cell.at(x, y));
}

}  // namespace

namespace {

struct SheetRow {
    const SphereFresnel* reference;
    const SphereFresnel* model;
};
using SheetRows = std::vector<SheetRow>;

// The sheet's passes. `library` and `run` are null when the graph is only planned (--explain): nothing executes.
// `scene` is the renderer's copy of `base`: only its sphere's Fresnel kind changes between cells.
graph::Handle<Json> add_sheet_passes(graph::PassGraph& graph, const Scene& base, Scene& scene,
                                     const std::vector<std::string>& materials, FresnelLibrary* library, PreviewRun* run) {
    using namespace graph;
    const Features features = plan_features(scene);
    const SceneInputs in = import_scene(graph, scene);
    const Handle<SheetRows> rows =
        graph
            .add_pass<Out<SheetRows>>(
                {"sheet-fresnel",
                 "per material (" + join(materials) + "): the reference LUT and the best fitted libfit model", Processor::cpu},
                [&](Builder& b, Out<SheetRows>& d) {
                    b.read(in.materials);
                    d.out = b.produce<SheetRows>("sheet-fresnel");
                },
                [&base, &materials, library, run](const Out<SheetRows>& d, Resources& r) {
                    SheetRows& result = r.emplace(d.out);
                    for (const std::string& name : materials) {
                        Sphere sphere = base.spheres[0];
                        sphere.material = name;
                        sphere.fresnel = ReferenceFresnel{};
                        const SphereFresnel& reference = library->get(sphere, "sheet material " + name);
                        sphere.fresnel = ModelFresnel{library->best_model(name), ParameterSource::fit};
                        result.push_back({&reference, &library->get(sphere, "sheet material " + name)});
                    }
                    if (!result.empty()) run->fresnel = {result.front().reference};
                })
            .out;
    const EnvironmentInputs environment = add_environment_passes(graph, scene, features, in, run);
    struct Cells {
        Handle<Image> image;
        Handle<Json> record;
    };
    const Cells& cells = graph.add_pass<Cells>(
        {"sheet-cells", "per material: reference | model | |difference| x 10, one GPU frame each", Processor::gpu},
        [&](Builder& b, Cells& d) {
            b.read(rows);
            environment.declare(b);
            d.image = b.produce<Image>("sheet-image");
            d.record = b.produce<Json>("sheet-record");
        },
        [&scene, rows, environment, run](const Cells& d, Resources& r) {
            GpuRenderer& gpu = run->renderer();
            environment.bind(gpu, r);
            const SheetRows& all = r.get(rows);
            Image& sheet = r.emplace(d.image, 3 * scene.width, static_cast<int>(all.size()) * scene.height);
            Json& record = r.emplace(d.record, Json::array());
            for (std::size_t row = 0; row < all.size(); ++row) {
                const SphereFresnel& model = *all[row].model;
                scene.spheres[0].fresnel = ReferenceFresnel{};
                gpu.set_fresnel(0, all[row].reference);
                const Image reference_image = gpu.render();
                scene.spheres[0].fresnel = ModelFresnel{model.fresnel, ParameterSource::fit};
                gpu.set_fresnel(0, &model);
                const Image model_image = gpu.render();
                const Image difference = absolute_difference(model_image, reference_image, kSheetDifferenceScale);
                paste(sheet, reference_image, 0, static_cast<int>(row));
                paste(sheet, model_image, 1, static_cast<int>(row));
                paste(sheet, difference, 2, static_cast<int>(row));
                double squared = 0;
                for (std::size_t i = 0; i < model_image.rgb.size(); ++i) {
                    const double diff = double(model_image.rgb[i]) - double(reference_image.rgb[i]);
                    squared += diff * diff;
                }
                record.push_back({{"row", row},
                                  {"material", model.material},
                                  {"source", model.source},
                                  {"model", model.fresnel},
                                  {"model_worst_rel_rms", model.worst_rel_rms},
                                  {"image_rmse_model_vs_reference", std::sqrt(squared / double(model_image.rgb.size()))}});
            }
        });
    add_image_file_pass(graph, "sheet.exr", cells.image, run);
    add_image_file_pass(graph, "sheet.png", cells.image, run);
    add_json_file_pass(graph, "sheet.json", "the rows' record", cells.record, run);
    graph.retain(cells.record);
    return cells.record;
}

void check_sheet_scene(const Scene& scene) {
    if (scene.spheres.size() != 1) throw InputError(InputLocation(scene.file, 0, "spheres"), "a sheet scene holds exactly one sphere");
}

}  // namespace

Plan build_sheet_plan(const Scene& base, const std::vector<std::string>& materials) {
    check_sheet_scene(base);
    Scene scene = base;
    graph::PassGraph graph;
    add_sheet_passes(graph, base, scene, materials, nullptr, nullptr);
    graph.compile();
    return plan_of(graph, plan_features(scene));
}

SphereSheet render_sphere_sheet(const Scene& base, const std::vector<std::string>& materials, const PreviewOptions& options,
                                GlContext* context) {
    check_sheet_scene(base);
    FresnelLibrary library(options.data_dir, options.ocio, base.space, base.file);
    Scene scene = base;
    PreviewRun run{scene, options.output_dir, options.ocio, options.threads, {}, context, {}, {}, {}, {}, {}, {}, {}};
    run.exr_colour = ExrColour{chromaticities_of(library.converter()), library.converter().space()};
    graph::PassGraph graph;
    const graph::Handle<Json> record = add_sheet_passes(graph, base, scene, materials, &library, &run);
    graph.before_first_gpu_pass([&run] { run.open_gl(); });
    graph.compile();
    graph.execute();
    run.commit_outputs();
    return {*graph.result(record), run.written};
}

}  // namespace metalfit::glpreview
