#include "glpreview/render/sphere_sheet.hpp"

#include <algorithm>
#include <cmath>
#include <fstream>
#include <numbers>
#include <optional>
#include <stdexcept>

#include "effects/glossy_localized/glossy_localized_effect.hpp"
#include "effects/glossy_prefiltered/glossy_prefiltered_effect.hpp"
#include "effects/lights/light.hpp"
#include "glpreview/io/image_io.hpp"
#include "glpreview/render/error_view.hpp"
#include "glpreview/render/gpu_renderer.hpp"
#include "glpreview/render/preview_passes.hpp"
#include "glpreview/render/sphere_fresnel.hpp"
#include "glpreview/render/sphere_metrics.hpp"
#include "glpreview/scene/glossy_choice.hpp"
#include "libfit/base/errors.hpp"
#include "libfit/base/json_text.hpp"
#include "libfit/base/number_text.hpp"
#include "libfit/base/text.hpp"

namespace metalfit::glpreview {
namespace {

void paste(Image& sheet, const Image& cell, int column, int row) {
    for (int y = 0; y < cell.height; ++y)
        for (int x = 0; x < cell.width; ++x) sheet.set(column * cell.width + x, row * cell.height + y, cell.at(x, y));
}

double image_rmse(const Image& a, const Image& b) {
    double squared = 0;
    for (std::size_t i = 0; i < a.rgb.size(); ++i) {
        const double diff = double(a.rgb[i]) - double(b.rgb[i]);
        squared += diff * diff;
    }
    return std::sqrt(squared / double(a.rgb.size()));
}

// Per material: the reference and the Fresnel of each model group (best[g]: group g asked for kBestModel).
struct SheetRow {
    const SphereFresnel* reference;
    std::vector<const SphereFresnel*> models;
    std::vector<bool> best;
};
using SheetRows = std::vector<SheetRow>;
using SheetCells = std::vector<SheetCell>;

// A row's Fresnel: the material `name` (with the request's layers) as the reference and each model group's.
SheetRow make_sheet_row(FresnelLibrary& library, const Scene& base, const SheetRequest& request,
                        const std::vector<std::string>& model_groups, const std::string& name) {
    Sphere sphere = base.spheres[0];
    sphere.material = name;
    sphere.film = request.film;
    sphere.coat = request.coat;
    sphere.fresnel = ReferenceFresnel{};
    SheetRow row{&library.get(sphere, "sheet material " + name), {}, {}};
    for (const std::string& group : model_groups) {
        const bool best = group == kBestModel;
        sphere.fresnel =
            ModelFresnel{best ? library.best_model(sphere, "sheet material " + name) : group, ParameterSource::fit};
        row.models.push_back(&library.get(sphere, "sheet material " + name));
        row.best.push_back(best);
    }
    return row;
}

// The roughness of the columns: those asked for, else the scene sphere's own; then the lit column's, if asked for.
std::vector<double> column_roughness(const Scene& base, const SheetRequest& request) {
    std::vector<double> roughness =
        request.roughness.empty() ? std::vector<double>{base.spheres[0].roughness} : request.roughness;
    if (request.light) roughness.push_back(kSheetLightRoughness);
    return roughness;
}

// A cell's roughness, and the glossy method the sphere's request gives at it.
void set_cell_roughness(Sphere& sphere, double roughness) {
    sphere.roughness = roughness;
    sphere.glossy = choose_glossy_method(roughness, sphere.glossy_request).method;
}

// The light of the lit column: a point light behind and beside the sphere, placed so that the mirror direction at
// the point whose normal is 60° from the view points at it (μ = v·h = 0.5 at the highlight's centre, down to
// grazing across the lobe: where the cheap models disagree), 6 radii from that point, its irradiance there 0.1
// (the highlight's peak near 1: not clipped by the display transform). Steeper angles make a highlight narrower
// than a pixel at the sheet's sizes.
Lights grazing_light(const Scene& scene) {
    const Sphere& sphere = scene.spheres[0];
    const Vec3 v = normalize(scene.camera.position - sphere.center);
    Vec3 side = cross(Vec3{0, 1, 0}, v);
    side = length(side) > 1e-9 ? normalize(side) : Vec3{1, 0, 0};
    const double angle = 60.0 * std::numbers::pi / 180;
    const Vec3 n = std::cos(angle) * v + std::sin(angle) * side;
    const Vec3 l = normalize(2 * dot(n, v) * n - v);
    const double distance = 6 * sphere.radius;
    Light light;
    light.position = sphere.center + sphere.radius * n + distance * l;
    light.intensity = 0.1 * distance * distance;
    return Lights{{light}};
}

std::string roughness_list(const std::vector<double>& roughness) {
    std::vector<std::string> text;
    for (double r : roughness) text.push_back(significant_text(r, 6));  // printf's %g
    return join(text);
}

// The cell at (column, row) of a sheet whose cells are w × h.
Image cell_of(const Image& sheet, int column, int row, int w, int h) {
    Image cell(w, h);
    for (int y = 0; y < h; ++y)
        for (int x = 0; x < w; ++x) cell.set(x, y, sheet.at(column * w + x, row * h + y));
    return cell;
}

// Every difference cell of `out` replaced by its error view (from the model and reference cells of `renders`, the
// sheet as rendered), one scale for the whole sheet, and a colour bar in each; returns the scale.
ErrorScale paint_error_views(Image& out, const Image& renders, const std::vector<SheetCell>& cells, int w, int h,
                             const LuminanceWeights& y) {
    std::vector<std::pair<const SheetCell*, std::vector<double>>> views;
    std::vector<double> all;
    for (const SheetCell& c : cells)
        if (c.kind == SheetCellKind::difference) {
            views.emplace_back(&c, relative_luminance_error(cell_of(renders, c.model_column, c.row, w, h),
                                                            cell_of(renders, c.reference_column, c.row, w, h), y));
            all.insert(all.end(), views.back().second.begin(), views.back().second.end());
        }
    const ErrorScale scale = error_scale_from(all);
    for (const auto& [c, errors] : views) {
        paint_error_view(out, c->column * w, c->row * h, w, h, errors, scale);
        const CellRect bar = colour_bar_rect(c->column, c->row, w, h);
        paint_colour_bar(out, bar.x, bar.y, bar.width, bar.height, scale);
    }
    return scale;
}

// A --sheet-rows row (`image`: its renders, `cells`: its labels, at row 0) as sheet.png draws a sheet — the exposure,
// the error views on the row's own scale, the labels — written to rows/<row>.png.
// Returns the row's error scale.
ErrorScale write_row_image(const Image& image, const SheetCells& cells, std::size_t row, bool labels,
                           const FresnelLibrary& library, PreviewRun& run) {
    const int w = run.scene.width, h = run.scene.height;
    Image out = exposed(image, run.exposure);
    const ErrorScale scale = paint_error_views(out, image, cells, w, h, luminance_weights(library.converter()));
    if (labels) draw_text(out, sheet_labels(cells, w, h, scale));
    if (run.output_dir.empty()) return scale;
    const std::filesystem::path file = run.output_file(sheet_row_image(row));  // sets run.display for a PNG
    write_png(file, out, *run.display);
    return scale;
}

// The sheet's passes. `library` and `run` are null when the graph is only planned (--explain): nothing executes.
// `scene` is the renderer's copy of `base` with the largest roughness asked for (what the environment passes plan
// for); only its sphere's Fresnel kind and roughness change between cells.
graph::Handle<Json> add_sheet_passes(graph::PassGraph& graph, const Scene& base, Scene& scene,
                                     const SheetRequest& request, FresnelLibrary* library, PreviewRun* run) {
    using namespace graph;
    const std::vector<double> roughness = column_roughness(base, request);
    set_cell_roughness(scene.spheres[0], *std::max_element(roughness.begin(), roughness.end()));
    Features features = plan_features(scene);
    for (double r : roughness) {  // each column's glossy method (auto chooses by roughness)
        Sphere column = scene.spheres[0];
        set_cell_roughness(column, r);
        add_glossy_features(features, column);
    }
    if (run) run->features = features;
    const SceneInputs in = import_scene(graph, scene);
    const std::vector<std::string> model_groups = sheet_model_groups(request);
    const std::string models = "models " + join(model_groups) + " (best: each material's best fitted libfit model)";
    const Handle<SheetRows> rows =
        graph
            .add_pass<Out<SheetRows>>(
                {"sheet-fresnel", "per material (" + join(request.materials) + "): the reference LUT and " + models,
                 Processor::cpu},
                [&](Builder& b, Out<SheetRows>& d) {
                    b.read(in.materials);
                    d.out = b.produce<SheetRows>("sheet-fresnel");
                },
                [&base, &request, model_groups, library, run](const Out<SheetRows>& d, Resources& r) {
                    SheetRows& result = r.emplace(d.out);
                    // --sheet-rows: the first row only (what the environment passes see); the others are made as
                    // they are rendered.
                    for (const std::string& name : request.materials) {
                        result.push_back(make_sheet_row(*library, base, request, model_groups, name));
                        if (request.row_images) break;
                    }
                    if (!result.empty()) run->fresnel = {result.front().reference};
                })
            .out;
    const EnvironmentInputs environment = add_environment_passes(graph, scene, features, in, run);
    std::optional<Handle<PrefilteredCube>> prefiltered;
    std::vector<Handle<DownsampledCube>> downsampled;
    if (features.prefiltered_map && environment.cube)
        prefiltered = add_prefilter_environment_pass(graph, scene, *environment.cube, run);
    else
        graph.skip("prefilter-environment", "no roughness column above 0 with glossy 'prefiltered'");
    if (environment.cube)
        for (int m : features.downsample_sizes)
            downsampled.push_back(add_downsample_environment_pass(graph, scene, m, *environment.cube, run));
    struct Cells {
        Handle<Image> image;
        Handle<Json> record;
        Handle<SheetCells> cells;
    };
    const int groups = static_cast<int>(model_groups.size());
    const Cells& cells = graph.add_pass<Cells>(
        {"sheet-cells",
         "per material: reference | model | difference for " + std::to_string(groups) +
             " model group(s) at roughness " + roughness_list(roughness) +
             (request.light ? " (the last lit by a point light grazing the sphere)" : "") +
             ", one GPU frame each (DFG tables of rough cells made on first use)" +
             (request.row_images ? "; each row labelled and written to rows/<row>.png as it is done (its Fresnel "
                                   "made for it and let go after it)"
                                 : ""),
         Processor::gpu},
        [&](Builder& b, Cells& d) {
            b.read(rows);
            environment.declare(b);
            if (prefiltered) b.read(*prefiltered);
            for (const auto& cube : downsampled) b.read(cube);
            d.image = b.produce<Image>("sheet-image");
            d.record = b.produce<Json>("sheet-record");
            d.cells = b.produce<SheetCells>("sheet-cell-labels");
            if (request.row_images) {
                b.write_file(sheet_row_image(0).replace(5, 1, "<row>"));
                b.write_file("sheet.json");
            }
        },
        [&scene, &base, &request, model_groups, rows, environment, prefiltered, downsampled, roughness, groups, run,
         library](const Cells& d, Resources& r) {
            const bool request_light = request.light, row_images = request.row_images;
            const auto& on_row = request.on_row;
            GpuRenderer& gpu = run->renderer();
            environment.bind(gpu, r);
            if (prefiltered) gpu.frame().put(r.get(*prefiltered));
            for (const auto& handle : downsampled) {
                const DownsampledCube& cube = r.get(handle);
                gpu.frame().put(cube, std::to_string(cube.m));
            }
            const SheetRows& made = r.get(rows);
            const std::size_t n_rows = request.materials.size();
            const int n_roughness = static_cast<int>(roughness.size());
            const int n_columns = static_cast<int>(sheet_columns(groups, n_roughness).size());
            // --sheet-rows: an image of one row, drawn again for each row.
            Image& sheet = r.emplace(d.image, n_columns * scene.width,
                                     static_cast<int>(row_images ? std::size_t{1} : n_rows) * scene.height);
            Json& record = r.emplace(d.record, Json::array());
            // --sheet-rows: sheet.json written a row at a time (the bytes of the whole record's dump(2)), the record
            // itself left empty, so that nothing of a row outlives it.
            std::ofstream record_file;
            const std::filesystem::path record_path =
                row_images && !run->output_dir.empty() ? run->output_file("sheet.json") : std::filesystem::path{};
            if (!record_path.empty()) record_file.open(record_path, std::ios::binary);
            std::size_t entries_written = 0;
            SheetCells& labels = r.emplace(d.cells);
            const auto light_column = [&scene, lit_column = request_light ? n_roughness - 1 : -1](int k) {
                if (k == lit_column)
                    scene.effects.set(grazing_light(scene));
                else
                    scene.effects = {};
                return k == lit_column;
            };
            for (std::size_t row = 0; row < n_rows; ++row) {
                // A --sheet-rows row past the first: its Fresnel made now and let go after the row (the first row's
                // stays: the environment passes were planned with it).
                std::optional<SheetRow> made_here;
                if (row_images && row > 0)
                    made_here = make_sheet_row(*library, base, request, model_groups, request.materials[row]);
                const SheetRow& this_row = made_here ? *made_here : made[row];
                const int y = row_images ? 0 : static_cast<int>(row);
                if (row_images) labels.clear();
                Json row_record = Json::array();
                Json& entries = row_images ? row_record : record;
                const std::string& material = this_row.reference->material;
                std::vector<Image> references;
                for (int k = 0; k < n_roughness; ++k) {
                    set_cell_roughness(scene.spheres[0], roughness[k]);
                    scene.spheres[0].fresnel = ReferenceFresnel{};
                    const bool lit = light_column(k);
                    gpu.set_fresnel(0, this_row.reference);
                    references.push_back(gpu.render());
                    const int column = sheet_column(SheetCellKind::reference, 0, k, n_roughness);
                    paste(sheet, references.back(), column, y);
                    labels.push_back({y, column, SheetCellKind::reference, material, {}, roughness[k], 0.0, lit});
                }
                for (int g = 1; g <= groups; ++g) {
                    const SphereFresnel& model = *this_row.models[g - 1];
                    const bool best = this_row.best[g - 1];
                    for (int k = 0; k < n_roughness; ++k) {
                        set_cell_roughness(scene.spheres[0], roughness[k]);
                        scene.spheres[0].fresnel = ModelFresnel{model.fresnel, ParameterSource::fit};
                        const bool lit = light_column(k);
                        gpu.set_fresnel(0, &model);
                        const Image model_image = gpu.render();
                        const Image difference = absolute_difference(model_image, references[k], kSheetDifferenceScale);
                        const int model_column = sheet_column(SheetCellKind::model, g, k, n_roughness);
                        const int difference_column = sheet_column(SheetCellKind::difference, g, k, n_roughness);
                        paste(sheet, model_image, model_column, y);
                        paste(sheet, difference, difference_column, y);
                        const double rmse = image_rmse(model_image, references[k]);
                        const int reference_column = sheet_column(SheetCellKind::reference, 0, k, n_roughness);
                        labels.push_back({y, model_column, SheetCellKind::model, material, model.fresnel, roughness[k],
                                          model.worst_rel_rms, lit, best});
                        labels.push_back({y, difference_column, SheetCellKind::difference, material, model.fresnel,
                                          roughness[k], rmse, lit, best, model_column, reference_column});
                        entries.push_back({{"row", row},
                                           {"material", model.material},
                                           {"source", model.source},
                                           {"model", model.fresnel},
                                           {"asked_for", best ? kBestModel : model.fresnel},
                                           {"model_worst_rel_rms", model.worst_rel_rms},
                                           {"image_rmse_model_vs_reference", rmse},
                                           {"roughness", roughness[k]},
                                           {"columns",
                                            {{"reference", reference_column},
                                             {"model", model_column},
                                             {"difference", difference_column}}}});
                        if (lit)
                            entries.back()["light"] =
                                "a point light beside and behind the sphere (the highlight where the normal is 60 degrees from the view)";
                    }
                }
                if (row_images) {
                    // The row's error scale in each of its entries: what its labels say, for a reader without them.
                    const ErrorScale scale = write_row_image(sheet, labels, row, request.labels, *library, *run);
                    for (Json& entry : row_record)
                        entry["error_view"] = {{"smallest", scale.smallest}, {"largest", scale.largest}};
                    // The row's Fresnel is let go: what the frame keeps for it goes first (its textures are keyed by
                    // address, which the next row's Fresnel may reuse).
                    if (made_here) {
                        gpu.forget_fresnel(*made_here->reference);
                        for (const SphereFresnel* model : made_here->models) gpu.forget_fresnel(*model);
                        std::vector<const SphereFresnel*> first_row{made[0].reference};
                        first_row.insert(first_row.end(), made[0].models.begin(), made[0].models.end());
                        library->keep_only(first_row);
                    }
                    for (const Json& entry : row_record)
                        record_file << (entries_written++ == 0 ? "[\n  " : ",\n  ")
                                    << indented_json(entry.dump(2), 1, 2);
                }
                if (on_row) on_row(row + 1, n_rows);
            }
            if (!record_path.empty()) {
                record_file << (entries_written == 0 ? "[]\n" : "\n]\n");
                record_file.close();
                if (!record_file) throw InputError(InputLocation(run->output_dir / "sheet.json"), "cannot write");
            }
        });
    if (request.row_images) {
        for (const char* pass : {"write sheet.exr", "sheet-error-views", "sheet-labels", "write sheet.png"})
            graph.skip(pass, "--sheet-rows: each row's image is written by sheet-cells");
        graph.skip("write sheet.json", "--sheet-rows: sheet-cells writes it a row at a time");
        graph.retain(cells.record);
        return cells.record;
    }
    add_image_file_pass(graph, "sheet.exr", cells.image, run);
    // sheet.png: the exposure on the renders, then the error views and their colour bars, then the labels, so that
    // neither changes with the exposure.
    struct ErrorViews {
        Handle<Image> image;
        Handle<ErrorScale> scale;
    };
    const ErrorViews& views = graph.add_pass<ErrorViews>(
        {"sheet-error-views",
         "exposure on the renders; each difference cell as the signed relative luminance error model / reference - 1 "
         "in false colour, one log scale for the sheet, with its colour bar; on sheet.png only",
         Processor::cpu},
        [&](Builder& b, ErrorViews& d) {
            b.read(cells.image);
            b.read(cells.cells);
            d.image = b.produce<Image>("sheet-display");
            d.scale = b.produce<ErrorScale>("sheet-error-scale");
        },
        [&scene, image = cells.image, labels = cells.cells, library, run](const ErrorViews& d, Resources& r) {
            const LuminanceWeights y = luminance_weights(library->converter());
            Image& out = r.emplace(d.image, exposed(r.get(image), run->exposure));
            r.emplace(d.scale, paint_error_views(out, r.get(image), r.get(labels), scene.width, scene.height, y));
        });
    if (request.labels) {
        const Handle<Image> labelled =
            graph
                .add_pass<Out<Image>>(
                    {"sheet-labels",
                     "material, model, roughness and error drawn in each cell's top and bottom band (OpenImageIO render_text, " +
                         std::string(kLabelFont) + "), on sheet.png only",
                     Processor::cpu},
                    [&](Builder& b, Out<Image>& d) {
                        b.read(views.image);
                        b.read(views.scale);
                        b.read(cells.cells);
                        d.out = b.produce<Image>("sheet-labelled");
                    },
                    [&scene, views, labels = cells.cells](const Out<Image>& d, Resources& r) {
                        Image& out = r.emplace(d.out, r.get(views.image));
                        draw_text(out, sheet_labels(r.get(labels), scene.width, scene.height, r.get(views.scale)));
                    })
                .out;
        add_image_file_pass(graph, "sheet.png", labelled, run, PngExposure::already_applied);
    } else {
        graph.skip("sheet-labels", "--sheet-labels off");
        add_image_file_pass(graph, "sheet.png", views.image, run, PngExposure::already_applied);
    }
    add_json_file_pass(graph, "sheet.json", "the cells' record", cells.record, run);
    graph.retain(cells.record);
    return cells.record;
}

void check_sheet_scene(const Scene& scene) {
    if (scene.spheres.size() != 1)
        throw InputError(InputLocation(scene.file, 0, "spheres"), "a sheet scene holds exactly one sphere");
}

}  // namespace

Plan build_sheet_plan(const Scene& base, const SheetRequest& request) {
    check_sheet_scene(base);
    check_sheet_request(request);
    Scene scene = base;
    graph::PassGraph graph;
    add_sheet_passes(graph, base, scene, request, nullptr, nullptr);
    graph.compile();
    return plan_of(graph, plan_features(scene));
}

SphereSheet render_sphere_sheet(const Scene& base, const SheetRequest& request, const PreviewOptions& options,
                                GlContext* context, const std::function<void(const SphereSheet&)>& before_commit) {
    check_sheet_scene(base);
    check_sheet_request(request);
    // The sheet's materials are the command line's (relative to the current folder), not files the scene names: no
    // scene-path policy for them (the environment the scene names is still read under it).
    FresnelLibrary library(options.data_dir, options.ocio, base.space, base.file);
    Scene scene = base;
    PreviewRun run{scene, options.output_dir, options.ocio, options.threads, {}, context, {}, {}, {}, {}, {}, {}, {}};
    run.exposure = std::exp2(options.exposure_ev);
    run.exr_colour = ExrColour{chromaticities_of(library.converter()), library.converter().space()};
    graph::PassGraph graph;
    const graph::Handle<Json> record = add_sheet_passes(graph, base, scene, request, &library, &run);
    graph.before_first_gpu_pass([&run] { run.open_gl(); });
    graph.compile();
    graph.execute();
    SphereSheet sheet{*graph.result(record), run.written};
    if (before_commit) before_commit(sheet);
    run.commit_outputs();
    return sheet;
}

}  // namespace metalfit::glpreview
