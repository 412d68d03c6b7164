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
#include "libfit/base/number_text.hpp"
#include "libfit/base/sample_statistics.hpp"
#include "libfit/base/standard_output.hpp"
#include "libfit/base/text.hpp"
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

using metalfit::fixed_text;
using metalfit::pad_left;
using metalfit::pad_right;
using metalfit::scientific_text;
using metalfit::significant_text;

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
    std::string text = "ms per frame (median of " + std::to_string(result.frame_ms.size()) +
                       "): " + fixed_text(result.frame_ms.empty() ? 0.0 : metalfit::median(result.frame_ms), 2) + "\n";
    for (const auto& s : result.metrics["spheres"]) {
        text += "sphere " + std::to_string(s["sphere"].get<int>()) + " " +
                pad_right(s["material"].get<std::string>(), 12) + " " + pad_right(s["fresnel"].get<std::string>(), 13) +
                " " + pad_right(s["mode"].get<std::string>(), 18) + " ";
        if (s["pixels"].get<std::size_t>() == 0) {
            text += "not visible (no pixel shows it)\n";
            continue;
        }
        text += "rmse " + fixed_text(s["rmse"].get<double>(), 5) + " mean_abs " +
                fixed_text(s["mean_abs"].get<double>(), 5);
        if (!s["mean_iterations"].is_null()) text += " mean steps " + fixed_text(s["mean_iterations"].get<double>(), 2);
        text += "\n";
    }
    std::cout << text;
}

// What a run prints on stdout, before its files are switched in: when stdout fails, flush_standard_output throws and
// nothing is written. (The renderer line on stderr comes after, with the outcome: print_renderer.)
void print_before_commit(const metalfit::glpreview::PreviewResult& result) {
    print_preview(result);
    metalfit::flush_standard_output();
}

// An image size as "WxH" from its [width, height].
std::string size_text(const nlohmann::ordered_json& size) {
    return std::to_string(size[0].get<int>()) + "x" + std::to_string(size[1].get<int>());
}

// One row of a Markdown table: "| a | b | c |" and the line's end.
std::string markdown_row(const std::vector<std::string>& cells) { return "| " + metalfit::join(cells, " | ") + " |\n"; }

// A ratio and its noise, "1.23 ± 0.04" (each to two decimals).
std::string ratio_text(const nlohmann::ordered_json& ratio, const nlohmann::ordered_json& noise) {
    return fixed_text(ratio.get<double>(), 2) + " ± " + fixed_text(noise.get<double>(), 2);
}

// The lines naming the models a CPU benchmark skipped, "\nskipped gulbrandsen (fit): why" each, and a line's end after
// the last.
std::string skipped_lines(const nlohmann::ordered_json& skipped) {
    std::string text;
    for (const auto& s : skipped)
        text += "\nskipped " + s["model"].get<std::string>() + " (" + s["params"].get<std::string>() +
                "): " + s["why"].get<std::string>();
    return skipped.empty() ? text : text + "\n";
}

// A GPU benchmark's rows as ratios to its mirror frame (--bench-lights, --bench-caustic-maps): a Markdown table.
std::string mirror_frame_ratios_table(const nlohmann::ordered_json& result) {
    std::string text = "renderer " + result["renderer"].get<std::string>() + "; " + size_text(result["size"]) + ", " +
                       std::to_string(result["rounds"].get<int>()) +
                       " interleaved rounds\n\n| variant | ms | ratio to the mirror frame |\n|---|---:|---:|\n";
    for (const auto& r : result["rows"])
        text += markdown_row({r["variant"].get<std::string>(), fixed_text(r["ms"].get<double>(), 3),
                              ratio_text(r["ratio_to_mirror_frame"], r["ratio_noise"])});
    return text;
}

// The compounding table of --bench-bounces as Markdown.
std::string bounces_table(const nlohmann::ordered_json& result) {
    std::string text = result["scene"].get<std::string>() + "; " + size_text(result["size"]) +
                       ", CPU. All: every sphere pixel; k-bounce paths: the pixels whose mirror path reaches bounce "
                       "k\n\n";
    text += "RGB reference vs spectral reference (the RGB rendering's own error):\n\n"
            "| bounce order | RMSE, all | dE2000 mean, all | dE2000 p95, all | k-bounce pixels | dE2000 mean, "
            "k-bounce | dE2000 p95, k-bounce |\n|---:|---:|---:|---:|---:|---:|---:|\n";
    for (const auto& r : result["rgb_vs_spectral"])
        text +=
            markdown_row({std::to_string(r["order"].get<int>()), scientific_text(r["rmse"].get<double>(), 2),
                          fixed_text(r["de2000_mean"].get<double>(), 3), fixed_text(r["de2000_p95"].get<double>(), 3),
                          std::to_string(r["reaching"]["pixels"].get<std::size_t>()),
                          fixed_text(r["reaching"]["de2000_mean"].get<double>(), 3),
                          fixed_text(r["reaching"]["de2000_p95"].get<double>(), 3)});
    text += "\nEach model against the RGB reference (reference LUTs along the same paths), and against the "
            "spectral one:\n\n| model | params | k | RMSE, all | dE2000 mean, all | dE2000 p95, all | "
            "dE2000 mean, k-bounce | dE2000 p95, k-bounce | dE2000 p95 vs spectral, k-bounce |\n"
            "|---|---|---:|---:|---:|---:|---:|---:|---:|\n";
    for (const auto& r : result["rows"])
        text += markdown_row(
            {r["model"].get<std::string>(), r["params"].get<std::string>(), std::to_string(r["order"].get<int>()),
             scientific_text(r["rmse"].get<double>(), 2), fixed_text(r["de2000_mean"].get<double>(), 3),
             fixed_text(r["de2000_p95"].get<double>(), 3), fixed_text(r["reaching"]["de2000_mean"].get<double>(), 3),
             fixed_text(r["reaching"]["de2000_p95"].get<double>(), 3),
             fixed_text(r["reaching_vs_spectral"]["de2000_p95"].get<double>(), 3)});
    return text + skipped_lines(result["skipped"]);
}

// A relative error in percent with its sign, "+1.25%" or "-0.40%" (printf's "%+.2f%%").
std::string signed_percent(const nlohmann::ordered_json& relative) {
    const double percent = 100 * relative.get<double>();
    return (std::signbit(percent) ? "" : "+") + fixed_text(percent, 2) + "%";
}

// Three numbers to four significant digits, "(0.1234, 5.678, 9)".
std::string triple_text(const nlohmann::ordered_json& v) {
    return "(" + significant_text(v[0].get<double>(), 4) + ", " + significant_text(v[1].get<double>(), 4) + ", " +
           significant_text(v[2].get<double>(), 4) + ")";
}

// The per-model caustic table of --bench-caustics as Markdown.
std::string caustics_table(const nlohmann::ordered_json& result) {
    std::string text = result["scene"].get<std::string>() + "; light " + result["light"].get<std::string>() + "; " +
                       std::to_string(result["photons"].get<int>()) + " photons, filter width " +
                       significant_text(result["filter_width"].get<double>(), 3) +
                       " m; CPU. Errors against the spectral reference (the worst channel, signed): total caustic "
                       "power, floor peak irradiance at the reference's peak, colour (each channel's share of the "
                       "power)\n";
    for (const auto& m : result["metals"]) {
        const auto& ref = m["reference"];
        text += "\n" + m["metal"].get<std::string>() + " (" + m["source"].get<std::string>() + "): reference power " +
                triple_text(ref["power"]) + " W, floor peak " + triple_text(ref["peak_irradiance"]) + " W/m2 at (" +
                fixed_text(ref["peak_position"][0].get<double>(), 3) + ", " +
                fixed_text(ref["peak_position"][2].get<double>(), 3) + ")";
        if (ref.contains("focus_distance"))
            text += ", " + fixed_text(ref["focus_distance"].get<double>(), 3) + " m from the closed form's cusp";
        text += "\n\n| model | params | power | peak | colour |\n|---|---|---:|---:|---:|\n";
        for (const auto& r : m["rows"])
            text += markdown_row({r["model"].get<std::string>(), r["params"].get<std::string>(),
                                  signed_percent(r["power_rel"]["worst"]), signed_percent(r["peak_rel"]["worst"]),
                                  signed_percent(r["colour_rel"]["worst"])});
        text += skipped_lines(m["skipped"]);
    }
    return text;
}

// --bench-lights beyond the mirror-frame table: a light's own passes.
std::string per_light_line(const nlohmann::ordered_json& result) {
    const auto& light = result["light_pass_per_light"];
    const auto& shadow = result["shadow_pass_per_light"];
    return "\nper light: light pass " + ratio_text(light["ratio_to_mirror_frame"], light["ratio_noise"]) +
           ", shadow pass " + ratio_text(shadow["ratio_to_mirror_frame"], shadow["ratio_noise"]) +
           " (ratios to the mirror frame)\n";
}

// --bench-interreflections: the frames at max_bounces 1-4 and the making of one sphere's map, as Markdown.
std::string interreflections_table(const nlohmann::ordered_json& result) {
    std::string text =
        "renderer " + result["renderer"].get<std::string>() + "; " + size_text(result["size"]) + ", maps " +
        std::to_string(result["map_size"].get<int>()) + "², " + std::to_string(result["rounds"].get<int>()) +
        " interleaved rounds\n\n| variant | ms | ratio to the one-bounce frame | vs the CPU reference: dE2000 mean, "
        "p95 | on the pixels reaching bounce k: mean, p95 (pixels) |\n|---|---:|---:|---:|---:|\n";
    for (const auto& r : result["rows"])
        text += markdown_row({r["variant"].get<std::string>(), fixed_text(r["ms"].get<double>(), 3),
                              ratio_text(r["ratio_to_one_bounce_frame"], r["ratio_noise"]),
                              fixed_text(r["vs_reference"]["de2000_mean"].get<double>(), 3) + ", " +
                                  fixed_text(r["vs_reference"]["de2000_p95"].get<double>(), 3),
                              fixed_text(r["vs_reference_reaching"]["de2000_mean"].get<double>(), 3) + ", " +
                                  fixed_text(r["vs_reference_reaching"]["de2000_p95"].get<double>(), 3) + " (" +
                                  std::to_string(r["reaching_pixels"].get<int>()) + ")"});
    const auto& update = result["map_update_per_sphere"];
    // The last two cells empty, as "| |" (markdown_row would write two spaces in each).
    return text + "| making one sphere's map (6 faces) | " + fixed_text(update["ms"].get<double>(), 3) + " | " +
           ratio_text(update["ratio_to_one_bounce_frame"], update["ratio_noise"]) + " | | |\n";
}

// --bench-glossy: roughness x rough method against the Monte-Carlo reference, then the shipped mirror scenes.
std::string glossy_table(const nlohmann::ordered_json& result) {
    std::string text = "renderer " + result["renderer"].get<std::string>() + "; " +
                       result["material"].get<std::string>() + " sphere (reference Fresnel), " +
                       size_text(result["size"]) + ", " + std::to_string(result["frames"].get<int>()) +
                       " interleaved rounds, Monte-Carlo reference " +
                       std::to_string(result["reference_samples"].get<int>()) + " samples per pixel\n\n";
    text += "| roughness | method | ms per frame | ratio to mirror classic | rmse | mean abs | reference noise |\n"
            "|---:|---|---:|---:|---:|---:|---:|\n";
    for (const auto& r : result["rows"])
        text += markdown_row({fixed_text(r["roughness"].get<double>(), 2), r["method"].get<std::string>(),
                              fixed_text(r["ms_per_frame"].get<double>(), 3),
                              ratio_text(r["ratio_to_mirror_classic"], r["ratio_noise"]),
                              fixed_text(r["rmse"].get<double>(), 4), fixed_text(r["mean_abs"].get<double>(), 4),
                              fixed_text(r["reference_noise"].get<double>(), 4)});
    text += "\n| mirror scene | size | spheres | ms per frame |\n|---|---|---:|---:|\n";
    for (const auto& m : result["mirror_scenes"])
        text += markdown_row({m["scene"].get<std::string>(), size_text(m["size"]),
                              std::to_string(m["spheres"].get<std::size_t>()),
                              fixed_text(m["ms_per_frame"].get<double>(), 2)});
    return text;
}

// --bench-shaders: each model's full-screen pass, "conductor-rgb      1.23 ms  x1.00 of conductor-rgb".
std::string shader_cost_lines(const nlohmann::ordered_json& result) {
    std::string text;
    for (const auto& m : result["models"])
        text += pad_right(m["model"].get<std::string>(), 14) + " " +
                pad_left(fixed_text(m["ms_per_frame"].get<double>(), 2), 8) + " ms  x" +
                fixed_text(m["ratio_to_conductor_rgb"].get<double>(), 2) + " of conductor-rgb\n";
    return text;
}

// --bench-localization: a line per room, reflection mode, strategy and iteration count.
std::string localization_lines(const nlohmann::ordered_json& result) {
    std::string text;
    for (const auto& room : result["rooms"])
        for (const auto& r : room["rows"])
            text += pad_right(room["room"].get<std::string>(), 10) + " " + pad_right(r["mode"].get<std::string>(), 18) +
                    " " + pad_right(r["strategy"].is_null() ? "-" : r["strategy"].get<std::string>(), 15) + " " +
                    pad_left(std::to_string(r["iterations"].get<int>()), 2) + " (mean " +
                    pad_left(fixed_text(r["mean_iterations"].get<double>(), 2), 5) + ") search " +
                    pad_left(std::to_string(r["search_steps"].get<int>()), 2) + "  " +
                    pad_left(fixed_text(r["ms_per_frame"].get<double>(), 2), 7) + " ms  x" +
                    ratio_text(r["ratio_to_classic"], r["ratio_noise"]) + "  rmse " +
                    fixed_text(r["rmse"].get<double>(), 5) + "\n";
    return text;
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
            std::cout << caustics_table(result);
            return ok;
        }
        if (bench_bounces_cost) {
            const PreviewOptions options{data_dir, choose_ocio_config(ocio_config, data_dir, "--ocio-config"), {}, 0};
            const auto result = bench_bounces(options, quick);
            if (json) {
                std::cout << result.dump(2) << "\n";
                return ok;
            }
            std::cout << bounces_table(result);
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
            std::cout << mirror_frame_ratios_table(result) + per_light_line(result);
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
            std::cout << mirror_frame_ratios_table(result) +
                             "\nthe article (Szirmay-Kalos et al. 2005, GPU of 2005): a 64² caustic map with shadows, "
                             "reflection and refraction at 50 FPS; 32² photons splatted into a 256² light map\n";
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
            std::cout << interreflections_table(result);
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
            std::cout << glossy_table(result);
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
            std::cout << "renderer " + result["renderer"].get<std::string>() + "\n" +
                             (bench_shader_cost ? shader_cost_lines(result) : localization_lines(result));
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
                std::cout << "sheet-progress " + std::to_string(done) + " " + std::to_string(total) + "\n"
                          << std::flush;
            };
        else if (terminal)
            sheet_request.on_row = [](std::size_t done, std::size_t total) {
                if (done < total)
                    std::fputs(
                        ("\rglpreview: sheet " + std::to_string(done) + "/" + std::to_string(total) + " rows").c_str(),
                        stderr);
                else
                    std::fputs(("\r" + std::string(40, ' ') + "\r").c_str(), stderr);  // the line cleared at the end
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
                std::string text;
                for (const auto& row : result.record) {
                    text += pad_right(row["material"].get<std::string>(), 12) + " reference | " +
                            pad_right(row["model"].get<std::string>(), 13) + " (worst-channel rel_rms " +
                            fixed_text(row["model_worst_rel_rms"].get<double>(), 4) + ") | |difference| x " +
                            significant_text(kSheetDifferenceScale, 6) + ": image RMSE " +
                            fixed_text(row["image_rmse_model_vs_reference"].get<double>(), 5);
                    if (!sheet_request.roughness.empty())
                        text += " at roughness " + significant_text(row["roughness"].get<double>(), 6);
                    text += "\n";
                }
                std::cout << text + (output_dir / (sheet_request.row_images ? "rows" : "sheet.png")).string() + "\n";
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
