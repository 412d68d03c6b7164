// glpreview: render a scene of metal spheres headless (EGL), exact Fresnel next to fitted models, under localized
// environment maps; CPU ray-traced reference, difference images and metrics. A thin layer over the glpreview library.
// Exit codes: 0 ok, 1 internal error, 2 usage, 3 bad input file, 4 colour configuration, 5 OpenGL/EGL failure.
#include <CLI/CLI.hpp>
#include <unistd.h>

#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <iostream>
#include <regex>
#include <set>
#include <sstream>

#include "glpreview/effects/caustic_maps_bench.hpp"
#include "glpreview/effects/caustics_bench.hpp"
#include "glpreview/effects/interreflections_bench.hpp"
#include "glpreview/effects/lights_bench.hpp"
#include "glpreview/gl/gl_context.hpp"
#include "glpreview/io/image_io.hpp"
#include "glpreview/render/bounces_bench.hpp"
#include "glpreview/render/gpu_bench.hpp"
#include "glpreview/render/plan.hpp"
#include "glpreview/render/preview.hpp"
#include "glpreview/render/reflection_probe.hpp"
#include "glpreview/render/sphere_sheet.hpp"
#include "glpreview/scene/glossy_choice.hpp"
#include "glpreview/scene/scene.hpp"
#include "help_formatter.hpp"
#include "libfit/base/data_dir.hpp"
#include "libfit/base/errors.hpp"
#include "libfit/base/library_logging.hpp"
#include "libfit/base/sample_statistics.hpp"
#include "libfit/base/standard_output.hpp"
#include "libfit/base/utf8.hpp"
#include "libfit/base/version.hpp"
#include "libfit/export/roughness.hpp"
#include "libfit/io/catalog.hpp"
#include "libfit/io/layer_materials.hpp"

namespace {

// libfit's exit codes (metalfit::ExitCode), and one more of the renderer's own.
constexpr int ok = metalfit::exit_ok, usage = metalfit::exit_usage, gl_failure = 5;

// "a,b,,c" → {"a", "b", "c"}.
std::vector<std::string> split_list(const std::string& text) {
    std::vector<std::string> items;
    std::stringstream list(text);
    for (std::string item; std::getline(list, item, ',');)
        if (!item.empty()) items.push_back(item);
    return items;
}

// One value of --sheet-roughness: libfit's roughness, a number in [0, 1].
double parse_roughness(const std::string& text) {
    if (const std::optional<double> value = metalfit::roughness_from_text(text)) return *value;
    throw metalfit::UsageError("--sheet-roughness: expected numbers in [0, 1], e.g. 0,0.2,0.5 (got '" +
                               text.substr(0, 40) + "')");
}

// --exposure EV: a finite number of stops in [-kMaxExposureStops, kMaxExposureStops].
constexpr double kMaxExposureStops = 32;
double parse_exposure(const std::string& text) {
    char* end = nullptr;
    const double ev = text.empty() ? NAN : std::strtod(text.c_str(), &end);
    if (!std::isfinite(ev) || *end != '\0' || std::abs(ev) > kMaxExposureStops)
        throw metalfit::UsageError("--exposure: expected a finite number of stops in [-32, 32], e.g. -2.5 (got '" +
                                   text.substr(0, 40) + "')");
    return ev;
}

}  // namespace

namespace {

// An image size WxH given to `option` (--size, --capture-probe).
std::pair<int, int> parse_size(const std::string& option, const std::string& size, const char* example) {
    using namespace metalfit::glpreview;
    std::smatch m;
    if (!std::regex_match(size, m, std::regex(R"((\d{1,4})x(\d{1,4}))")) || std::stoi(m[1]) < 1 ||
        std::stoi(m[2]) < 1 || std::stoi(m[1]) > kMaxImageEdge || std::stoi(m[2]) > kMaxImageEdge ||
        static_cast<long long>(std::stoi(m[1])) * std::stoi(m[2]) > kMaxImagePixels)
        throw metalfit::UsageError(option + ": expected WxH with each side in [1, " + std::to_string(kMaxImageEdge) +
                                   "] and at most " + std::to_string(kMaxImagePixels) + " pixels, e.g. " + example +
                                   " (got '" + size.substr(0, 40) + "')");
    return {std::stoi(m[1]), std::stoi(m[2])};
}

// --size WxH over the scene's image size (nothing when empty).
void apply_size(metalfit::glpreview::Scene& scene, const std::string& size) {
    if (size.empty()) return;
    std::tie(scene.width, scene.height) = parse_size("--size", size, "512x512");
}

// The files a preview wrote, its frame time and each sphere's error, one line each.
void print_renderer(const metalfit::glpreview::PreviewResult& result) {
    if (!result.renderer.empty()) std::cerr << "glpreview: renderer " << result.renderer << "\n";
}

void print_preview(const metalfit::glpreview::PreviewResult& result) {
    for (const auto& file : result.written) std::cout << file.string() << "\n";
    if (result.metrics.is_null()) return;
    std::printf("ms per frame (median of %zu): %.2f\n", result.frame_ms.size(),
                result.frame_ms.empty() ? 0.0 : metalfit::median(result.frame_ms));
    for (const auto& s : result.metrics["spheres"]) {
        std::printf("sphere %d %-12s %-13s %-18s ", s["sphere"].get<int>(), s["material"].get<std::string>().c_str(),
                    s["fresnel"].get<std::string>().c_str(), s["mode"].get<std::string>().c_str());
        if (s["pixels"].get<std::size_t>() == 0)
            std::printf("not visible (no pixel shows it)\n");
        else if (s["mean_iterations"].is_null())
            std::printf("rmse %.5f mean_abs %.5f\n", s["rmse"].get<double>(), s["mean_abs"].get<double>());
        else
            std::printf("rmse %.5f mean_abs %.5f mean steps %.2f\n", s["rmse"].get<double>(),
                        s["mean_abs"].get<double>(), s["mean_iterations"].get<double>());
    }
}

// What a run prints on stdout, before its files are switched in: when stdout fails, flush_standard_output throws and
// nothing is written. (The renderer line on stderr comes after, with the outcome: print_renderer.)
void print_before_commit(const metalfit::glpreview::PreviewResult& result) {
    print_preview(result);
    metalfit::flush_standard_output();  // cout and the printf lines (stdio) both
}

// The compounding table of --bench-bounces as Markdown.
// A GPU benchmark's rows as ratios to its mirror frame (--bench-lights, --bench-caustic-maps): a Markdown table.
void print_mirror_frame_ratios(const nlohmann::ordered_json& result) {
    std::printf(
        "renderer %s; %dx%d, %d interleaved rounds\n\n| variant | ms | ratio to the mirror frame |\n|---|---:|---:|\n",
        result["renderer"].get<std::string>().c_str(), result["size"][0].get<int>(), result["size"][1].get<int>(),
        result["rounds"].get<int>());
    for (const auto& r : result["rows"])
        std::printf("| %s | %.3f | %.2f ± %.2f |\n", r["variant"].get<std::string>().c_str(), r["ms"].get<double>(),
                    r["ratio_to_mirror_frame"].get<double>(), r["ratio_noise"].get<double>());
}

void print_bounces_table(const nlohmann::ordered_json& result) {
    std::printf("%s; %dx%d, CPU. All: every sphere pixel; k-bounce paths: the pixels whose mirror path reaches "
                "bounce k\n\n",
                result["scene"].get<std::string>().c_str(), result["size"][0].get<int>(), result["size"][1].get<int>());
    std::printf("RGB reference vs spectral reference (the RGB rendering's own error):\n\n"
                "| bounce order | RMSE, all | dE2000 mean, all | dE2000 p95, all | k-bounce pixels | dE2000 mean, "
                "k-bounce | dE2000 p95, k-bounce |\n|---:|---:|---:|---:|---:|---:|---:|\n");
    for (const auto& r : result["rgb_vs_spectral"])
        std::printf("| %d | %.2e | %.3f | %.3f | %zu | %.3f | %.3f |\n", r["order"].get<int>(), r["rmse"].get<double>(),
                    r["de2000_mean"].get<double>(), r["de2000_p95"].get<double>(),
                    r["reaching"]["pixels"].get<std::size_t>(), r["reaching"]["de2000_mean"].get<double>(),
                    r["reaching"]["de2000_p95"].get<double>());
    std::printf("\nEach model against the RGB reference (reference LUTs along the same paths), and against the "
                "spectral one:\n\n| model | params | k | RMSE, all | dE2000 mean, all | dE2000 p95, all | "
                "dE2000 mean, k-bounce | dE2000 p95, k-bounce | dE2000 p95 vs spectral, k-bounce |\n"
                "|---|---|---:|---:|---:|---:|---:|---:|---:|\n");
    for (const auto& r : result["rows"])
        std::printf("| %s | %s | %d | %.2e | %.3f | %.3f | %.3f | %.3f | %.3f |\n",
                    r["model"].get<std::string>().c_str(), r["params"].get<std::string>().c_str(),
                    r["order"].get<int>(), r["rmse"].get<double>(), r["de2000_mean"].get<double>(),
                    r["de2000_p95"].get<double>(), r["reaching"]["de2000_mean"].get<double>(),
                    r["reaching"]["de2000_p95"].get<double>(), r["reaching_vs_spectral"]["de2000_p95"].get<double>());
    for (const auto& s : result["skipped"])
        std::printf("\nskipped %s (%s): %s", s["model"].get<std::string>().c_str(),
                    s["params"].get<std::string>().c_str(), s["why"].get<std::string>().c_str());
    if (!result["skipped"].empty()) std::printf("\n");
}

// The per-model caustic table of --bench-caustics as Markdown.
void print_caustics_table(const nlohmann::ordered_json& result) {
    std::printf("%s; light %s; %d photons, filter width %.3g m; CPU. Errors against the spectral reference (the "
                "worst channel, signed): total caustic power, floor peak irradiance at the reference's peak, colour "
                "(each channel's share of the power)\n",
                result["scene"].get<std::string>().c_str(), result["light"].get<std::string>().c_str(),
                result["photons"].get<int>(), result["filter_width"].get<double>());
    for (const auto& m : result["metals"]) {
        const auto& ref = m["reference"];
        std::printf("\n%s (%s): reference power (%.4g, %.4g, %.4g) W, floor peak (%.4g, %.4g, %.4g) W/m2 at (%.3f, "
                    "%.3f)",
                    m["metal"].get<std::string>().c_str(), m["source"].get<std::string>().c_str(),
                    ref["power"][0].get<double>(), ref["power"][1].get<double>(), ref["power"][2].get<double>(),
                    ref["peak_irradiance"][0].get<double>(), ref["peak_irradiance"][1].get<double>(),
                    ref["peak_irradiance"][2].get<double>(), ref["peak_position"][0].get<double>(),
                    ref["peak_position"][2].get<double>());
        if (ref.contains("focus_distance"))
            std::printf(", %.3f m from the closed form's cusp", ref["focus_distance"].get<double>());
        std::printf("\n\n| model | params | power | peak | colour |\n|---|---|---:|---:|---:|\n");
        for (const auto& r : m["rows"])
            std::printf("| %s | %s | %+.2f%% | %+.2f%% | %+.2f%% |\n", r["model"].get<std::string>().c_str(),
                        r["params"].get<std::string>().c_str(), 100 * r["power_rel"]["worst"].get<double>(),
                        100 * r["peak_rel"]["worst"].get<double>(), 100 * r["colour_rel"]["worst"].get<double>());
        for (const auto& s : m["skipped"])
            std::printf("\nskipped %s (%s): %s", s["model"].get<std::string>().c_str(),
                        s["params"].get<std::string>().c_str(), s["why"].get<std::string>().c_str());
        if (!m["skipped"].empty()) std::printf("\n");
    }
}

int run_glpreview(int argc, char** argv) {
    using namespace metalfit;
    using namespace metalfit::glpreview;

    CLI::App app{"glpreview: metal spheres, exact vs fitted Fresnel, under localized environment maps (headless EGL)"};
    app.formatter(std::make_shared<metalfit::cli_help::HelpFormatter>());  // within 100 columns
    app.set_version_flag("--version", std::string("glpreview (metalfit ") + METALFIT_VERSION + ")");
    std::vector<std::filesystem::path> scene_files;
    std::filesystem::path output_dir = "preview";
    std::string size;
    bool explain_only = false;
    std::filesystem::path data_dir = default_data_dir();
    std::optional<std::filesystem::path> ocio_config;
    app.add_option("scene", scene_files, "Scene JSON (docs/scene.md); several with --batch");
    bool batch = false;
    app.add_flag("--batch", batch,
                 "Render every scene given, each into OUTPUT/<scene file's stem>/, in one process and one GL context");
    bool bench_shader_cost = false, bench_localization_cost = false, bench_glossy_cost = false,
         bench_lights_cost = false, bench_caustic_maps_cost = false, bench_interreflections_cost = false,
         bench_bounces_cost = false, bench_caustics_cost = false, quick = false, json = false;
    app.add_flag(
        "--bench-shaders", bench_shader_cost,
        "Benchmark: full-screen 1024² pass per libfit model, ratio to the exact conductor-rgb pass (JSON with --json)");
    app.add_flag(
        "--bench-localization", bench_localization_cost,
        "Benchmark: ms per frame and error vs the CPU reference for every reflection mode and iteration count");
    app.add_flag(
        "--bench-glossy", bench_glossy_cost,
        "Benchmark: roughness x rough method, ms per frame as a ratio to the mirror classic pass, RMSE vs the Monte-Carlo "
        "reference; the shipped mirror scenes' ms per frame (a Markdown table; JSON with --json)");
    app.add_flag(
        "--bench-lights", bench_lights_cost,
        "Benchmark: a rough sphere's frame with 0, 1 and 4 point lights and one light's shadow pass, as ratios to the "
        "mirror frame (a Markdown table; JSON with --json)");
    app.add_flag("--bench-caustic-maps", bench_caustic_maps_cost,
                 "Benchmark: one light's caustic map and its splat into the room's light maps at 32²-256² photons, as "
                 "ratios to the ring scene's mirror frame (a Markdown table; JSON with --json)");
    app.add_flag(
        "--bench-interreflections", bench_interreflections_cost,
        "Benchmark: four mirror spheres' frame at max_bounces 1-4 and the making of one sphere's distance map, as "
        "ratios to the one-bounce frame (a Markdown table; JSON with --json)");
    app.add_flag(
        "--bench-bounces", bench_bounces_cost,
        "Benchmark (CPU only): gold, copper, silver and aluminium mirrors reflecting each other, bounce orders 1-4, "
        "every model's image RMSE and dE2000 against the RGB reference and the RGB-vs-spectral error (a Markdown "
        "table; JSON with --json)");
    app.add_flag(
        "--bench-caustics", bench_caustics_cost,
        "Benchmark (CPU only): a gold, copper and aluminium ring under a grazing directional light, every model's "
        "caustic power, peak irradiance and colour against the spectral photon-traced reference (a Markdown table; "
        "JSON with --json)");
    app.add_flag("--quick", quick, "Benchmarks: fewer frames, smaller images");
    app.add_flag("--json", json, "Benchmarks: print JSON");
    app.add_option("-o,--output", output_dir, "Output folder (default: preview/)");
    app.add_option("--size", size,
                   "Image size WxH (overrides the scene's image; each side 1-8192, at most 4096² pixels)");
    bool allow_paths_outside = false;
    app.add_flag("--allow-paths-outside", allow_paths_outside,
                 "Let the scene read files outside its own folder and the database (absolute paths, ../)");
    bool glossy_as_asked = false;
    app.add_flag("--glossy-as-asked", glossy_as_asked,
                 "Render glossy 'localized' wherever a scene asks for it, also below the roughness where the measured "
                 "table says it fails (for measuring that table: scripts/measure-glossy-choice.py)");
    std::string sheet;
    app.add_option(
        "--sheet", sheet,
        "Sphere sheet instead of the scene's outputs: comma-separated materials, one row each "
        "(reference | model | difference: in sheet.png the signed error model/reference - 1 in false colour, "
        "in sheet.exr |model - reference| x 10); the scene holds one sphere");
    std::string sheet_models = "best", sheet_roughness, sheet_labels = "on", sheet_light = "off";
    app.add_option("--sheet-models", sheet_models,
                   "Sheet: the models shown, comma-separated, one column group each: libfit ids and best (each "
                   "material's best fitted model), e.g. best,f82-tint,schlick")
        ->capture_default_str();
    app.add_option("--sheet-roughness", sheet_roughness,
                   "Sheet: the roughness of the columns, comma-separated in [0, 1], e.g. 0,0.2,0.5 (default: the scene "
                   "sphere's)");
    app.add_option("--sheet-labels", sheet_labels,
                   "Sheet: material, model, roughness and error drawn on sheet.png (on|off)")
        ->capture_default_str();
    app.add_option(
        "--sheet-light", sheet_light,
        "Sheet: one more column at roughness 0.35 under a point light beside and behind the sphere, each model's highlight next "
        "to the reference's (on|off; a room environment)");
    bool sheet_progress = false;
    app.add_flag("--sheet-progress", sheet_progress,
                 "Sheet: a line `sheet-progress DONE TOTAL` on stdout after each row (for programs that run the "
                 "sheet: metalfit report); on a terminal stderr shows the rows done without it");
    bool sheet_rows = false;
    app.add_flag("--sheet-rows", sheet_rows,
                 "Sheet: each row its own labelled image, rows/<row>.png (from 0), written as the row is done, and "
                 "sheet.json; no sheet.exr or sheet.png (memory of one row, whatever the number of materials)");
    std::string sheet_film, sheet_coat;
    app.add_option("--sheet-film", sheet_film,
                   "Sheet: a thin film over every row's metal, as metalfit --film (TiO2:80nm, 2.2:120nm, a file)");
    app.add_option(
        "--sheet-coat", sheet_coat,
        "Sheet: a clear coat over every row's metal (and film), as metalfit --coat (1.5, PMMA:20um, a file)");
    std::string exposure = "0";
    app.add_option("--exposure", exposure,
                   "Exposure in stops applied to the PNGs' radiance before the display transform (never to EXRs; the "
                   "sheet's labels and error views are drawn after it)")
        ->capture_default_str();
    std::string capture_probe_size;
    app.add_option("--capture-probe", capture_probe_size,
                   "Capture the scene's environment from its reference point as a WxH equirect reflection probe: "
                   "OUTPUT/probe.exr and OUTPUT/probe.json (the scene with that image on the matching proxy)");
    app.add_flag("--explain", explain_only,
                 "Print the plan (passes, why they run, what is skipped) and render nothing");
    app.add_option("--data-dir", data_dir, "Built-in database folder")->check(CLI::ExistingDirectory);
    app.add_option("--ocio-config", ocio_config, "OCIO config when $OCIO is not set (default: data/ocio/config.ocio)");

    try {
        require_utf8_arguments(argc, argv);  // before any value becomes a path or a name in a record (docs/cli.md)
    } catch (...) {
        return report_current_exception("glpreview");
    }
    try {
        app.parse(argc, argv);
    } catch (const CLI::ParseError& e) {
        const int code = app.exit(e);
        return code == 0 ? ok : usage;
    }
    try {
        if (bench_caustics_cost) {
            const PreviewOptions options{data_dir, choose_ocio_config(ocio_config, data_dir, "--ocio-config"), {}, 0};
            const auto result = bench_caustics(options, quick);
            if (json) {
                std::cout << result.dump(2) << "\n";
                return ok;
            }
            print_caustics_table(result);
            return ok;
        }
        if (bench_bounces_cost) {
            const PreviewOptions options{data_dir, choose_ocio_config(ocio_config, data_dir, "--ocio-config"), {}, 0};
            const auto result = bench_bounces(options, quick);
            if (json) {
                std::cout << result.dump(2) << "\n";
                return ok;
            }
            print_bounces_table(result);
            return ok;
        }
        if (bench_lights_cost) {
            GlContext context = GlContext::create();
            const PreviewOptions options{data_dir, choose_ocio_config(ocio_config, data_dir, "--ocio-config"), {}, 0};
            const auto result = bench_lights(context, options, quick);
            if (json) {
                std::cout << result.dump(2) << "\n";
                return ok;
            }
            print_mirror_frame_ratios(result);
            std::printf("\nper light: light pass %.2f ± %.2f, shadow pass %.2f ± %.2f (ratios to the mirror frame)\n",
                        result["light_pass_per_light"]["ratio_to_mirror_frame"].get<double>(),
                        result["light_pass_per_light"]["ratio_noise"].get<double>(),
                        result["shadow_pass_per_light"]["ratio_to_mirror_frame"].get<double>(),
                        result["shadow_pass_per_light"]["ratio_noise"].get<double>());
            return ok;
        }
        if (bench_caustic_maps_cost) {
            GlContext context = GlContext::create();
            const PreviewOptions options{data_dir, choose_ocio_config(ocio_config, data_dir, "--ocio-config"), {}, 0};
            const auto result = bench_caustic_maps(context, options, quick);
            if (json) {
                std::cout << result.dump(2) << "\n";
                return ok;
            }
            print_mirror_frame_ratios(result);
            std::printf("\nthe article (Szirmay-Kalos et al. 2005, GPU of 2005): a 64² caustic map with shadows, "
                        "reflection and refraction at 50 FPS; 32² photons splatted into a 256² light map\n");
            return ok;
        }
        if (bench_interreflections_cost) {
            GlContext context = GlContext::create();
            const PreviewOptions options{data_dir, choose_ocio_config(ocio_config, data_dir, "--ocio-config"), {}, 0};
            const auto result = bench_interreflections(context, options, quick);
            if (json) {
                std::cout << result.dump(2) << "\n";
                return ok;
            }
            std::printf(
                "renderer %s; %dx%d, maps %d², %d interleaved rounds\n\n| variant | ms | ratio to the one-bounce "
                "frame | vs the CPU reference: dE2000 mean, p95 | on the pixels reaching bounce k: mean, p95 (pixels) "
                "|\n|---|---:|---:|---:|---:|\n",
                result["renderer"].get<std::string>().c_str(), result["size"][0].get<int>(),
                result["size"][1].get<int>(), result["map_size"].get<int>(), result["rounds"].get<int>());
            for (const auto& r : result["rows"])
                std::printf("| %s | %.3f | %.2f ± %.2f | %.3f, %.3f | %.3f, %.3f (%d) |\n",
                            r["variant"].get<std::string>().c_str(), r["ms"].get<double>(),
                            r["ratio_to_one_bounce_frame"].get<double>(), r["ratio_noise"].get<double>(),
                            r["vs_reference"]["de2000_mean"].get<double>(),
                            r["vs_reference"]["de2000_p95"].get<double>(),
                            r["vs_reference_reaching"]["de2000_mean"].get<double>(),
                            r["vs_reference_reaching"]["de2000_p95"].get<double>(), r["reaching_pixels"].get<int>());
            const auto& update = result["map_update_per_sphere"];
            std::printf("| making one sphere's map (6 faces) | %.3f | %.2f ± %.2f | | |\n", update["ms"].get<double>(),
                        update["ratio_to_one_bounce_frame"].get<double>(), update["ratio_noise"].get<double>());
            return ok;
        }
        if (bench_glossy_cost) {
            GlContext context = GlContext::create();
            const PreviewOptions options{data_dir, choose_ocio_config(ocio_config, data_dir, "--ocio-config"), {}, 0};
            const auto result = bench_glossy(context, options, quick);
            if (json) {
                std::cout << result.dump(2) << "\n";
                return ok;
            }
            std::printf(
                "renderer %s; %s sphere (reference Fresnel), %dx%d, %d interleaved rounds, Monte-Carlo reference %d samples per pixel\n\n",
                result["renderer"].get<std::string>().c_str(), result["material"].get<std::string>().c_str(),
                result["size"][0].get<int>(), result["size"][1].get<int>(), result["frames"].get<int>(),
                result["reference_samples"].get<int>());
            std::printf(
                "| roughness | method | ms per frame | ratio to mirror classic | rmse | mean abs | reference noise |\n"
                "|---:|---|---:|---:|---:|---:|---:|\n");
            for (const auto& r : result["rows"])
                std::printf("| %.2f | %s | %.3f | %.2f ± %.2f | %.4f | %.4f | %.4f |\n", r["roughness"].get<double>(),
                            r["method"].get<std::string>().c_str(), r["ms_per_frame"].get<double>(),
                            r["ratio_to_mirror_classic"].get<double>(), r["ratio_noise"].get<double>(),
                            r["rmse"].get<double>(), r["mean_abs"].get<double>(), r["reference_noise"].get<double>());
            std::printf("\n| mirror scene | size | spheres | ms per frame |\n|---|---|---:|---:|\n");
            for (const auto& m : result["mirror_scenes"])
                std::printf("| %s | %dx%d | %zu | %.2f |\n", m["scene"].get<std::string>().c_str(),
                            m["size"][0].get<int>(), m["size"][1].get<int>(), m["spheres"].get<std::size_t>(),
                            m["ms_per_frame"].get<double>());
            return ok;
        }
        if (bench_shader_cost || bench_localization_cost) {
            GlContext context = GlContext::create();
            const PreviewOptions options{data_dir, choose_ocio_config(ocio_config, data_dir, "--ocio-config"), {}, 0};
            const auto result = bench_shader_cost ? bench_shaders(context, options, quick)
                                                  : bench_localization(context, options, quick);
            if (json) {
                std::cout << result.dump(2) << "\n";
                return ok;
            }
            std::cout << "renderer " << result["renderer"].get<std::string>() << "\n";
            if (bench_shader_cost)
                for (const auto& m : result["models"])
                    std::printf("%-14s %8.2f ms  x%.2f of conductor-rgb\n", m["model"].get<std::string>().c_str(),
                                m["ms_per_frame"].get<double>(), m["ratio_to_conductor_rgb"].get<double>());
            else
                for (const auto& room : result["rooms"])
                    for (const auto& r : room["rows"])
                        std::printf(
                            "%-10s %-18s %-15s %2d (mean %5.2f) search %2d  %7.2f ms  x%.2f ± %.2f  rmse %.5f\n",
                            room["room"].get<std::string>().c_str(), r["mode"].get<std::string>().c_str(),
                            r["strategy"].is_null() ? "-" : r["strategy"].get<std::string>().c_str(),
                            r["iterations"].get<int>(), r["mean_iterations"].get<double>(),
                            r["search_steps"].get<int>(), r["ms_per_frame"].get<double>(),
                            r["ratio_to_classic"].get<double>(), r["ratio_noise"].get<double>(),
                            r["rmse"].get<double>());
            return ok;
        }
        if (scene_files.empty())
            throw UsageError(
                "a scene file is required (or --bench-shaders / --bench-localization / --bench-glossy / --bench-lights / "
                "--bench-caustic-maps / --bench-bounces / --bench-caustics)");
        if (scene_files.size() > 1 && !batch) throw UsageError("several scene files need --batch");
        if (batch && (!sheet.empty() || explain_only || !capture_probe_size.empty()))
            throw UsageError("--batch renders scenes: --sheet, --explain and --capture-probe take one scene");
        if (!capture_probe_size.empty() && (!sheet.empty() || explain_only || !size.empty()))
            throw UsageError("--capture-probe renders nothing else: not with --sheet, --explain or --size");
        const auto load = [&](const std::filesystem::path& scene_file) {
            Scene scene = load_scene(scene_file);
            if (glossy_as_asked) honour_glossy_requests(scene);
            confine_scene_paths(scene, {data_dir, allow_paths_outside});
            scene.paths = PathPolicy{data_dir, allow_paths_outside};  // checked again on each file's descriptor
            apply_size(scene, size);
            for (const std::string& warning : scene.warnings) std::cerr << "glpreview: warning: " << warning << "\n";
            return scene;
        };
        if (batch) {
            // Every scene is read and checked before anything is rendered; the stems name the output folders.
            std::vector<Scene> scenes;
            std::set<std::string> stems;
            for (const auto& file : scene_files) {
                // The stem names a folder inside -o: "...json" (stem "..") or ".json" must not name -o's parent or -o.
                const std::string stem = file.stem().string();
                if (stem.empty() || stem == "." || stem == ".." || stem.find('/') != std::string::npos)
                    throw UsageError("--batch: " + file.string() + ": the scene's name '" + stem +
                                     "' cannot name its output folder inside " + output_dir.string() +
                                     " (rename the scene file)");
                if (!stems.insert(file.stem().string()).second)
                    throw UsageError("--batch: two scenes named '" + file.stem().string() +
                                     "' would write the same folder");
                scenes.push_back(load(file));
            }
            const OcioConfigChoice ocio = choose_ocio_config(ocio_config, data_dir, "--ocio-config");
            GlContext context = GlContext::create();
            for (std::size_t i = 0; i < scenes.size(); ++i)
                print_renderer(run_preview(scenes[i], {data_dir, ocio, output_dir / scene_files[i].stem(), 0}, &context,
                                           print_before_commit));
            return ok;
        }
        Scene scene = load(scene_files.front());
        if (!capture_probe_size.empty()) {
            const auto [width, height] = parse_size("--capture-probe", capture_probe_size, "1024x512");
            const ReflectionProbe probe =
                capture_probe(scene, choose_ocio_config(ocio_config, data_dir, "--ocio-config"), width, height);
            for (const char* name : {"probe.exr", "probe.json"}) std::cout << (output_dir / name).string() << "\n";
            flush_standard_output();  // a stdout that fails: nothing written
            write_probe(probe, output_dir);
            return ok;
        }
        // --sheet materials given as files are the user's paths: relative to the current folder, not to the scene's.
        SheetRequest sheet_request;
        for (const std::string& m : split_list(sheet))
            sheet_request.materials.push_back(looks_like_path(m) ? std::filesystem::absolute(m).string() : m);
        sheet_request.models = split_list(sheet_models);
        const double exposure_ev = parse_exposure(exposure);
        for (const std::string& r : split_list(sheet_roughness)) sheet_request.roughness.push_back(parse_roughness(r));
        if (sheet_labels != "on" && sheet_labels != "off")
            throw UsageError("--sheet-labels: on or off (got '" + sheet_labels.substr(0, 40) + "')");
        sheet_request.labels = sheet_labels == "on";
        if (sheet_light != "on" && sheet_light != "off")
            throw UsageError("--sheet-light: on or off (got '" + sheet_light.substr(0, 40) + "')");
        sheet_request.light = sheet_light == "on";
        // Layer files, like the materials, are the user's paths: relative to the current folder.
        const auto layer = [](const std::string& text, const char* option) {
            if (text.empty()) return text;
            LayerArgument a = parse_layer_argument(option, text);
            if (!looks_like_path(a.material)) return text;
            return std::filesystem::absolute(a.material).string() +
                   (a.thickness_nm ? text.substr(text.rfind(':')) : std::string());
        };
        const bool terminal = isatty(STDERR_FILENO) != 0;
        if (sheet_progress)
            sheet_request.on_row = [](std::size_t done, std::size_t total) {
                std::printf("sheet-progress %zu %zu\n", done, total);
                std::fflush(stdout);
            };
        else if (terminal)
            sheet_request.on_row = [](std::size_t done, std::size_t total) {
                if (done < total)
                    std::fprintf(stderr, "\rglpreview: sheet %zu/%zu rows", done, total);
                else
                    std::fprintf(stderr, "\r%40s\r", "");  // the line cleared once the last row is done
            };
        sheet_request.row_images = sheet_rows;
        sheet_request.film = layer(sheet_film, "--sheet-film");
        sheet_request.coat = layer(sheet_coat, "--sheet-coat");
        if (sheet_request.light && scene.environment.type != EnvironmentType::room)
            throw UsageError(
                "--sheet-light: the light column needs a room environment (its surfaces receive the light)");
        if (sheet.empty() &&
            (sheet_models != "best" || !sheet_roughness.empty() || sheet_labels != "on" || sheet_light != "off" ||
             !sheet_film.empty() || !sheet_coat.empty() || sheet_progress || sheet_rows))
            throw UsageError(
                "--sheet-models, --sheet-roughness, --sheet-labels, --sheet-light, --sheet-film, --sheet-coat, "
                "--sheet-progress and --sheet-rows need --sheet");
        if (!sheet.empty()) check_sheet_request(sheet_request);
        if (explain_only) {
            std::cout << explain(sheet.empty() ? build_plan(scene) : build_sheet_plan(scene, sheet_request), scene);
            return ok;
        }
        PreviewOptions options{data_dir, choose_ocio_config(ocio_config, data_dir, "--ocio-config"), output_dir, 0,
                               exposure_ev};
        if (!sheet.empty()) {
            // Printed before the sheet is switched in: a stdout that fails writes nothing. With --sheet-rows the
            // record is in sheet.json only (nothing of a row is kept): the folder alone is printed.
            const auto print_sheet = [&](const SphereSheet& result) {
                for (const auto& row : result.record) {
                    std::printf(
                        "%-12s reference | %-13s (worst-channel rel_rms %.4f) | |difference| x %g: image RMSE %.5f",
                        row["material"].get<std::string>().c_str(), row["model"].get<std::string>().c_str(),
                        row["model_worst_rel_rms"].get<double>(), kSheetDifferenceScale,
                        row["image_rmse_model_vs_reference"].get<double>());
                    if (!sheet_request.roughness.empty())
                        std::printf(" at roughness %g", row["roughness"].get<double>());
                    std::printf("\n");
                }
                std::cout << (output_dir / (sheet_request.row_images ? "rows" : "sheet.png")).string() << "\n";
                flush_standard_output();  // a stdout that fails: nothing written
            };
            render_sphere_sheet(scene, sheet_request, options, nullptr, print_sheet);
            return ok;
        }
        print_renderer(run_preview(scene, options, nullptr, print_before_commit));
        return ok;
    } catch (const GlError& e) {
        std::cerr << "glpreview: " << e.what() << "\n";
        return gl_failure;
    } catch (...) {
        return report_current_exception("glpreview");
    }
}

}  // namespace

#if defined(__SANITIZE_ADDRESS__)
// Under AddressSanitizer (the asan preset), no leak check at exit: Mesa's EGL/llvmpipe driver, loaded with dlopen,
// leaves a few allocations behind at exit (frames in "<unknown module>"). Whoever runs glpreview — metalfit report,
// the schema and PNG-chunk tests — would otherwise see a failure for a leak that is not glpreview's; preview_tests
// run with detect_leaks=0 for the same reason. LeakSanitizer asks this hook at exit, whatever $ASAN_OPTIONS says
// (the asan test preset sets detect_leaks=1). Every other sanitizer check stays on.
extern "C" int __lsan_is_turned_off() { return 1; }
#endif

int main(int argc, char** argv) {
    metalfit::route_library_logging("glpreview");
    return metalfit::finish_standard_output("glpreview", run_glpreview(argc, argv));
}
