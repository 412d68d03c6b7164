// The glpreview command line end to end: files written, exit codes, one-line errors, nothing half-written.
#include <gtest/gtest.h>

#include <cstdio>
#include <fstream>
#include <nlohmann/json.hpp>
#include <set>

#include <sys/stat.h>

#include "glpreview/io/image_io.hpp"
#include "glpreview/render/environment.hpp"
#include "glpreview/scene/scene.hpp"
#include "libfit/base/errors.hpp"
#include "libfit/models/model.hpp"
#include "test_support.hpp"

namespace metalfit::test {
namespace test_preview_cli {

using CommandRun = CommandResult;

CommandRun glpreview(const std::string& arguments, const TempDir& dir) {
    return run_command(kGlpreviewExe, arguments, dir.path());
}

TEST(PreviewCli, MalformedSceneIsOneLineErrorExit3AndWritesNothing) {
    TempDir dir;
    const fs::path scene = dir.write("bad.json", R"({"spheres": [{"center": [0, 1, 0], "iterations": -2}]})");
    const CommandRun run = glpreview(scene.string() + " -o " + (dir.path() / "out").string(), dir);
    EXPECT_EQ(run.exit_code, 3);
    EXPECT_TRUE(Contains(run.err, "bad.json: spheres[0].iterations: must be in [0, 64]"));
    EXPECT_EQ(std::count(run.err.begin(), run.err.end(), '\n'), 1) << run.err;
    EXPECT_FALSE(fs::exists(dir.path() / "out"));
}

TEST(PreviewCli, UnknownMaterialNamesTheField) {
    TempDir dir;
    const fs::path scene = dir.write("s.json", R"({"spheres": [{"center": [0, 1, 0], "material": "unobtainium"}]})");
    const CommandRun run = glpreview(scene.string() + " -o " + (dir.path() / "out").string(), dir);
    EXPECT_EQ(run.exit_code, 3);
    EXPECT_TRUE(Contains(run.err, "spheres[0].material"));
}

TEST(PreviewCli, BatchRendersEveryScenesFilesAsSeparateRunsDo) {
    TempDir dir;
    const fs::path room = dir.write("room.json", R"({"image": {"width": 40, "height": 30},
        "spheres": [{"center": [0, 1, 0], "radius": 0.5, "material": "Cu", "fresnel": "schlick"}]})");
    const fs::path rough = dir.write("rough.json", R"({"image": {"width": 32, "height": 24},
        "spheres": [{"center": [0, 1, 0], "radius": 0.5, "roughness": 0.4}], "outputs": {"reference_samples": 8}})");
    const CommandRun batch =
        glpreview("--batch " + room.string() + " " + rough.string() + " -o " + (dir.path() / "batch").string(), dir);
    ASSERT_EQ(batch.exit_code, 0) << batch.err;
    for (const char* stem : {"room", "rough"}) {
        const CommandRun single = glpreview((dir.path() / (std::string(stem) + ".json")).string() + " -o " +
                                                (dir.path() / "single" / stem).string(),
                                            dir);
        ASSERT_EQ(single.exit_code, 0) << single.err;
        // One GL context for both scenes changes nothing in what each writes (PNGs carry no date).
        for (const char* file : {"beauty.png", "reference.png", "difference.png"})
            EXPECT_EQ(read_file(dir.path() / "batch" / stem / file), read_file(dir.path() / "single" / stem / file))
                << stem << "/" << file;
        EXPECT_TRUE(Contains(batch.out, (dir.path() / "batch" / stem / "beauty.png").string()));
    }
}

TEST(PreviewCli, BatchChecksEverySceneFirstAndRefusesWhatItCannotDo) {
    TempDir dir;
    const fs::path good = dir.write("good.json", R"({"spheres": [{"center": [0, 1, 0]}]})");
    const fs::path bad = dir.write("bad.json", R"({"spheres": [{"center": [0, 1, 0], "roughness": 2}]})");
    fs::create_directories(dir.path() / "other");
    const fs::path same_stem = dir.write("other/good.json", R"({"spheres": [{"center": [0, 1, 0]}]})");
    const std::string out = " -o " + (dir.path() / "out").string();
    const CommandRun broken = glpreview("--batch " + good.string() + " " + bad.string() + out, dir);
    EXPECT_EQ(broken.exit_code, 3);
    EXPECT_TRUE(Contains(broken.err, "bad.json: spheres[0].roughness")) << broken.err;
    EXPECT_FALSE(fs::exists(dir.path() / "out")) << "the good scene was rendered before the bad one was read";
    const CommandRun twice = glpreview("--batch " + good.string() + " " + same_stem.string() + out, dir);
    EXPECT_EQ(twice.exit_code, 2);
    EXPECT_TRUE(Contains(twice.err, "two scenes named 'good'")) << twice.err;
    const CommandRun without = glpreview(good.string() + " " + same_stem.string() + out, dir);
    EXPECT_EQ(without.exit_code, 2);
    EXPECT_TRUE(Contains(without.err, "several scene files need --batch")) << without.err;
    const CommandRun sheet = glpreview("--batch --sheet Au " + good.string() + out, dir);
    EXPECT_EQ(sheet.exit_code, 2);
    EXPECT_FALSE(fs::exists(dir.path() / "out"));
}

TEST(PreviewCli, ExplainPrintsThePlanAndRendersNothing) {
    TempDir dir;
    const fs::path scene = dir.write("s.json", R"({"spheres": [{"center": [0, 1, 0], "reflection": "classic"}],
                                                    "outputs": {"difference": false}})");
    const CommandRun run = glpreview(scene.string() + " --explain -o " + (dir.path() / "out").string(), dir);
    EXPECT_EQ(run.exit_code, 0) << run.err;
    EXPECT_TRUE(Contains(run.out, "capture-environment"));
    EXPECT_TRUE(Contains(run.out, "distance channel: no sphere uses the distance impostor"));
    EXPECT_TRUE(Contains(run.out, "difference: culled"));
    EXPECT_FALSE(fs::exists(dir.path() / "out"));
}

TEST(PreviewCli, WritesTheRequestedFilesAndMetrics) {
    TempDir dir;
    const fs::path scene = dir.write("s.json", R"({"image": {"width": 64, "height": 48},
        "camera": {"position": [0, 1.2, 2.5], "look_at": [0, 1, 0]},
        "spheres": [{"center": [-0.5, 1, 0], "radius": 0.4, "material": "Cu", "fresnel": "schlick", "reflection": "box-parallax"},
                    {"center": [0.5, 1, 0], "radius": 0.4, "strategy": "mixed", "iterations": 2}],
        "outputs": {"png": false}})");
    const CommandRun run = glpreview(scene.string() + " -o " + (dir.path() / "out").string(), dir);
    ASSERT_EQ(run.exit_code, 0) << run.err;
    std::vector<std::string> files;
    for (const auto& entry : fs::directory_iterator(dir.path() / "out"))
        files.push_back(entry.path().filename().string());
    std::sort(files.begin(), files.end());
    // fit-error.exr: a sphere uses a model (its error apart from the localization's, signed, linear); delta-e.exr:
    // ΔE2000 per pixel beside it.
    EXPECT_EQ(files, (std::vector<std::string>{"beauty.exr", "delta-e.exr", "difference.exr", "fit-error.exr",
                                               "metrics.json", "reference.exr", "timings.json"}));
    const auto metrics = nlohmann::json::parse(read_file(dir.path() / "out" / "metrics.json"));
    const auto timings = nlohmann::json::parse(read_file(dir.path() / "out" / "timings.json"));
    ASSERT_EQ(metrics["spheres"].size(), 2u);
    EXPECT_EQ(metrics["spheres"][0]["material"], "copper");
    EXPECT_EQ(metrics["spheres"][0]["mode"], "box-parallax");
    EXPECT_TRUE(metrics["spheres"][0]["strategy"].is_null());
    EXPECT_EQ(metrics["spheres"][1]["strategy"], "mixed");
    EXPECT_EQ(metrics["spheres"][1]["iterations"], 2);
    EXPECT_FALSE(metrics.contains("frame_ms"));  // timings apart: metrics.json is the same on every run
    // A second run of the same scene writes the same metrics.json, byte for byte (the timings differ, apart).
    const CommandRun again = glpreview(scene.string() + " -o " + (dir.path() / "again").string(), dir);
    ASSERT_EQ(again.exit_code, 0) << again.err;
    EXPECT_EQ(read_file(dir.path() / "again" / "metrics.json"), read_file(dir.path() / "out" / "metrics.json"));
    EXPECT_GE(timings["frame_ms"].size(), 5u);
    EXPECT_GT(timings["ms_per_frame"].get<double>(), 0.0);
    // The frame clock follows the renderer: CPU time of the process on llvmpipe (issue 29), wall on a hardware GPU.
    const bool software = timings["renderer"].get<std::string>().find("llvmpipe") != std::string::npos;
    EXPECT_EQ(timings["clock"], software ? "process-cpu" : "wall") << timings["renderer"];
    for (const auto& s : metrics["spheres"]) {
        EXPECT_GT(s["pixels"].get<int>(), 100);
        EXPECT_GE(s["rmse"].get<double>(), s["mean_abs"].get<double>());  // RMS ≥ mean of |·|
    }
}

// Issue 18 item 5, issue 13 items 7–9 end to end: the exit codes and one-line messages.
TEST(PreviewCli, SceneValidationGaps) {
    TempDir dir;
    const fs::path scene =
        dir.write("s.json", R"({"image": {"width": 24, "height": 16}, "spheres": [{"center": [0, 1, 0]}],
                                                  "outputs": {"png": false}})");
    CommandRun run = glpreview(scene.string() + " --size 8193x10 --explain", dir);
    EXPECT_EQ(run.exit_code, 2);
    EXPECT_TRUE(Contains(run.err, "--size: expected WxH with each side in [1, 8192]")) << run.err;
    EXPECT_EQ(glpreview(scene.string() + " --size 8192x2048 --explain", dir).exit_code, 0);
    EXPECT_EQ(glpreview(scene.string() + " --size 4096x4097 --explain", dir).exit_code, 2);

    const fs::path overflow = dir.write("overflow.json", R"({"spheres": [{"center": [0, 1, 1e999]}]})");
    run = glpreview(overflow.string() + " --explain", dir);
    EXPECT_EQ(run.exit_code, 3);
    EXPECT_TRUE(Contains(run.err, "overflow.json:1: spheres[0].center[2]: number beyond the range of a double"))
        << run.err;
    EXPECT_EQ(std::count(run.err.begin(), run.err.end(), '\n'), 1) << run.err;

    const fs::path outside =
        dir.write("outside.json", R"({"spheres": [{"center": [0, 1, 0], "material": "/etc/hostname.csv"}]})");
    run = glpreview(outside.string() + " --explain", dir);
    EXPECT_EQ(run.exit_code, 3);
    EXPECT_TRUE(Contains(run.err, "spheres[0].material: a path outside the scene's folder and the database"))
        << run.err;
    EXPECT_EQ(glpreview(outside.string() + " --explain --allow-paths-outside", dir).exit_code, 0);

    // A sphere behind the camera: "not visible", not "nan"; warnings for what the scene asks that means nothing.
    const fs::path hidden =
        dir.write("hidden.json", R"({"image": {"width": 24, "height": 16}, "camera": {"position": [0, 1.2, 2.5]},
        "spheres": [{"center": [0, 1, 0], "radius": 0.4, "reflection": "classic", "iterations": 3}, {"center": [0, 1, 2.9], "radius": 0.05}],
        "outputs": {"png": false, "localization": true}})");
    run = glpreview(hidden.string() + " -o " + (dir.path() / "out").string(), dir);
    ASSERT_EQ(run.exit_code, 0) << run.err;
    EXPECT_TRUE(
        Contains(run.out, "sphere 1 gold         reference     distance-impostor  not visible (no pixel shows it)"))
        << run.out;
    EXPECT_FALSE(Contains(run.out, "nan"));
    EXPECT_TRUE(Contains(run.err, "warning: " + hidden.string() + ": spheres[0].iterations: ignored")) << run.err;
    EXPECT_TRUE(fs::exists(dir.path() / "out" / "localization.exr"));
}

// An output that cannot be replaced (a folder where beauty.exr should go, which root cannot overwrite either):
// a one-line error naming the file, exit 3, and no temporary file left behind.
TEST(PreviewCli, AnOutputThatCannotBeWrittenIsAnErrorAndLeavesNoPartialFile) {
    TempDir dir;
    const fs::path scene =
        dir.write("s.json", R"({"image": {"width": 16, "height": 16}, "spheres": [{"center": [0, 1.5, 0]}],
                                                  "outputs": {"png": false, "reference": false, "difference": false, "metrics": false}})");
    fs::create_directories(dir.path() / "out" / "beauty.exr" / "occupied");
    const CommandRun run = glpreview(scene.string() + " -o " + (dir.path() / "out").string(), dir);
    EXPECT_EQ(run.exit_code, 3);
    EXPECT_TRUE(Contains(run.err, "beauty.exr")) << run.err;
    EXPECT_EQ(std::count(run.err.begin(), run.err.end(), '\n'), 1) << run.err;
    std::vector<std::string> left;
    for (const auto& entry : fs::directory_iterator(dir.path() / "out"))
        left.push_back(entry.path().filename().string());
    EXPECT_EQ(left, (std::vector<std::string>{"beauty.exr"}));
}

// issue 13, item 4: the outputs are one unit: when a later one cannot be written, the earlier ones are not left.
TEST(PreviewCli, ALaterOutputThatFailsLeavesNoEarlierOne) {
    TempDir dir;
    const fs::path scene =
        dir.write("s.json", R"({"image": {"width": 16, "height": 16}, "spheres": [{"center": [0, 1.5, 0]}],
                                                  "outputs": {"png": false, "difference": false}})");
    fs::create_directories(dir.path() / "out" / "metrics.json" / "occupied");  // written after beauty and reference
    const CommandRun run = glpreview(scene.string() + " -o " + (dir.path() / "out").string(), dir);
    EXPECT_EQ(run.exit_code, 3) << run.err;
    EXPECT_EQ(std::count(run.err.begin(), run.err.end(), '\n'), 1) << run.err;
    std::vector<std::string> left;
    for (const auto& entry : fs::directory_iterator(dir.path() / "out"))
        left.push_back(entry.path().filename().string());
    EXPECT_EQ(left, (std::vector<std::string>{"metrics.json"}));  // no beauty.exr, no reference.exr
}

// The benchmark modes `metalfit bench` reads: every libfit model and the LUT timed in one run; every reflection
// mode and iteration count with its error against the CPU reference.
TEST(PreviewCli, BenchmarkModesPrintTheirJson) {
    TempDir dir;
    CommandRun run = glpreview("--bench-shaders --quick --json", dir);
    ASSERT_EQ(run.exit_code, 0) << run.err;
    auto shaders = nlohmann::json::parse(run.out);
    std::set<std::string> models;
    for (const auto& m : shaders["models"]) {
        models.insert(m["model"].get<std::string>());
        EXPECT_GT(m["ms_per_frame"].get<double>(), 0.0);
    }
    std::set<std::string> expected{"reference-lut"};  // every registered model and the reference LUT
    for (const metalfit::Model* m : metalfit::all_models()) expected.insert(std::string(m->id()));
    EXPECT_EQ(models, expected);
    run = glpreview("--bench-localization --quick --json", dir);
    ASSERT_EQ(run.exit_code, 0) << run.err;
    auto localization = nlohmann::json::parse(run.out);
    ASSERT_EQ(localization["rooms"].size(), 2u);
    for (const auto& room : localization["rooms"]) {
        const auto& rows = room["rows"];
        // classic, box-parallax, 5 strategies × {0, 1, 2, 4, 8, 16}, the default with 4 other linear searches
        ASSERT_EQ(rows.size(), 36u);
        std::set<int> default_searches;
        for (const auto& r : rows)
            if (r["strategy"] == "illinois" && r["iterations"] == 8)
                default_searches.insert(r["search_steps"].get<int>());
        EXPECT_EQ(default_searches, (std::set<int>{0, 4, 8, 16, 32}));
        EXPECT_EQ(rows[0]["mode"], "classic");
        EXPECT_DOUBLE_EQ(rows[0]["ratio_to_classic"].get<double>(), 1.0);
        for (const auto& r : rows) {
            EXPECT_GE(r["ratio_noise"].get<double>(), 0.0);
            EXPECT_LE(r["mean_iterations"].get<double>(), r["iterations"].get<double>() + 1e-9) << r["strategy"];
            if (r["mode"] == "distance-impostor" && r["iterations"].get<int>() > 0) {
                EXPECT_GT(r["mean_iterations"].get<double>(), 0.0) << r["strategy"];
            }
        }
        for (const auto& r : rows)
            if (r["mode"] == "distance-impostor" && r["iterations"] == 4) {
                EXPECT_LT(r["rmse"].get<double>(), rows[0]["rmse"].get<double>())
                    << room["room"] << " " << r["strategy"];
            }
    }
}

TEST(PreviewCli, TheLightsBenchmarkPrintsItsRatiosToTheMirrorFrame) {
    TempDir dir;
    const CommandRun run = glpreview("--bench-lights --quick --json", dir);
    ASSERT_EQ(run.exit_code, 0) << run.err;
    const auto lights = nlohmann::json::parse(run.out);
    const auto& rows = lights["rows"];
    ASSERT_EQ(rows.size(), 5u);  // the mirror frame, the rough frame with 0, 1, 4 lights, one shadow pass
    EXPECT_DOUBLE_EQ(rows[0]["ratio_to_mirror_frame"].get<double>(), 1.0);
    for (const auto& r : rows) {
        EXPECT_GT(r["ms"].get<double>(), 0.0);
        EXPECT_GE(r["ratio_noise"].get<double>(), 0.0);
    }
    // Lights cost something: four lights' frame is slower than none (the per-round ratios' median).
    EXPECT_GT(rows[3]["ratio_to_mirror_frame"].get<double>(), rows[1]["ratio_to_mirror_frame"].get<double>());
    EXPECT_GT(lights["shadow_pass_per_light"]["ratio_to_mirror_frame"].get<double>(), 0.0);
}

TEST(PreviewCli, TheBouncesBenchmarkPrintsTheCompoundingTableOnTheCpu) {
    TempDir dir;
    const CommandRun run = glpreview("--bench-bounces --quick", dir);
    ASSERT_EQ(run.exit_code, 0) << run.err;
    EXPECT_TRUE(Contains(run.out, "| bounce order | RMSE, all |"));
    for (const Model* model : all_models())
        EXPECT_TRUE(Contains(run.out, "| " + std::string(model->id()) + " | fit | 4 |")) << model->id();
    const CommandRun json = glpreview("--bench-bounces --quick --json", dir);
    ASSERT_EQ(json.exit_code, 0) << json.err;
    EXPECT_EQ(nlohmann::json::parse(json.out)["orders"], 4);
}

// A one-sphere scene under the shipped equirect sky (a user's HDRI): the sheet renders under it.
fs::path write_equirect_sheet_scene(const TempDir& dir) {
    return dir.write("sky-sheet.json", R"({"image": {"width": 48, "height": 48},
        "camera": {"position": [0, 0.2, 3.0], "look_at": [0, 0.2, 0], "fov_y_deg": 30},
        "environment": {"type": "equirect", "file": ")" +
                                           (kData / "scenes" / "sky.hdr").string() + R"(", "intensity": 1.0},
        "spheres": [{"center": [0, 0.2, 0], "radius": 0.5, "reflection": "classic"}]})");
}

TEST(PreviewCli, SheetRendersUnderAnEquirectEnvironment) {
    TempDir dir;
    const fs::path scene = write_equirect_sheet_scene(dir);
    const CommandRun run = glpreview(scene.string() + " --sheet Au -o " + (dir.path() / "out").string(), dir);
    ASSERT_EQ(run.exit_code, 0) << run.err;
    EXPECT_TRUE(fs::exists(dir.path() / "out" / "sheet.png"));
    const auto record = nlohmann::json::parse(read_file(dir.path() / "out" / "sheet.json"));
    ASSERT_EQ(record.size(), 1u);
    EXPECT_EQ(record[0]["material"], "gold");
}

// --capture-probe: the room seen from its reference point as an equirect, and the scene that renders it on the room's
// box; what each texel holds is what the CPU tracer sees along that texel's direction.
TEST(PreviewCli, CaptureProbeWritesTheRoomAsAnEquirectOnItsOwnBox) {
    TempDir dir;
    const fs::path room =
        dir.write("room.json", R"({"environment": {"type": "room", "min": [-2, 0, -3], "max": [4, 2.5, 3],
        "ceiling": [0.3, 0.4, 0.5], "panels": [], "wall_x_max": [0.1, 0.2, 0.7], "reference_point": [0.5, 1.25, 0.25], "cube_size": 64},
        "spheres": [{"center": [0, 1, 0], "radius": 0.5, "material": "Cu", "roughness": 0.3}]})");
    const CommandRun run = glpreview(room.string() + " --capture-probe 64x32 -o " + (dir.path() / "out").string(), dir);
    ASSERT_EQ(run.exit_code, 0) << run.err;
    EXPECT_TRUE(Contains(run.out, (dir.path() / "out" / "probe.exr").string()));
    const glpreview::Scene source = glpreview::load_scene(room);
    const glpreview::Scene probe = glpreview::load_scene(dir.path() / "out" / "probe.json");
    ASSERT_EQ(probe.environment.type, glpreview::EnvironmentType::equirect);
    ASSERT_TRUE(probe.environment.equirect.proxy.has_value());
    const auto* box = std::get_if<glpreview::BoxProxy>(&*probe.environment.equirect.proxy);
    ASSERT_NE(box, nullptr);
    EXPECT_EQ(box->min.x, -2);
    EXPECT_EQ(box->max.x, 4);
    EXPECT_EQ(box->max.y, 2.5);
    EXPECT_EQ(probe.environment.reference().x, 0.5);
    EXPECT_EQ(probe.environment.reference().z, 0.25);
    EXPECT_EQ(probe.environment.cube_size, 64);
    EXPECT_EQ(probe.environment.equirect.colorspace, "Linear Rec.709 (sRGB)");
    ASSERT_EQ(probe.spheres.size(), 1u);
    EXPECT_EQ(probe.spheres[0].roughness, 0.3);

    const glpreview::Image image = glpreview::read_image(dir.path() / "out" / "probe.exr");
    ASSERT_EQ(image.width, 64);
    ASSERT_EQ(image.height, 32);
    const glpreview::EnvironmentTracer tracer(source.environment);
    for (int y = 0; y < image.height; ++y)
        for (int x = 0; x < image.width; ++x) {
            const RGB seen =
                tracer.trace(source.environment.reference(), glpreview::equirect_direction(x, y, 64, 32)).radiance;
            ASSERT_NEAR(image.at(x, y).b, seen.b, 1e-3 * seen.b + 1e-6) << x << "," << y;  // half floats
        }
    // Independent of the tracer: the top row looks at the plain ceiling, the texel at u = 0.75 on the middle rows at
    // the +x wall (its checker shades by 1 or 0.75).
    EXPECT_NEAR(image.at(5, 0).g, 0.4, 1e-3);
    const double wall = image.at(48, 15).b;
    EXPECT_TRUE(std::abs(wall - 0.7) < 1e-3 || std::abs(wall - 0.525) < 1e-3) << wall;

    // A sphere room gives its sphere; an image at infinity has no proxy; the size is checked.
    const fs::path sphere_room = dir.write("sphere-room.json", R"({"environment": {"type": "sphere-room", "radius": 6},
        "spheres": [{"center": [0, 0, 0], "radius": 0.5}]})");
    ASSERT_EQ(
        glpreview(sphere_room.string() + " --capture-probe 16x8 -o " + (dir.path() / "sphere").string(), dir).exit_code,
        0);
    const glpreview::Scene sphere_probe = glpreview::load_scene(dir.path() / "sphere" / "probe.json");
    EXPECT_EQ(std::get<glpreview::SphereProxy>(*sphere_probe.environment.equirect.proxy).radius, 6);
    const CommandRun infinity = glpreview(
        write_equirect_sheet_scene(dir).string() + " --capture-probe 16x8 -o " + (dir.path() / "sky").string(), dir);
    EXPECT_EQ(infinity.exit_code, 2);
    EXPECT_TRUE(Contains(infinity.err, "image at infinity")) << infinity.err;
    EXPECT_EQ(std::count(infinity.err.begin(), infinity.err.end(), '\n'), 1) << infinity.err;
    EXPECT_FALSE(fs::exists(dir.path() / "sky"));
    const CommandRun size = glpreview(room.string() + " --capture-probe 0x8 -o " + (dir.path() / "bad").string(), dir);
    EXPECT_EQ(size.exit_code, 2);
    EXPECT_TRUE(Contains(size.err, "--capture-probe: expected WxH")) << size.err;
}

TEST(PreviewCli, ExplainWithSheetPrintsTheSheetsPlan) {
    TempDir dir;
    const fs::path scene = write_equirect_sheet_scene(dir);
    const CommandRun run =
        glpreview(scene.string() + " --sheet Au,Cu --explain -o " + (dir.path() / "out").string(), dir);
    ASSERT_EQ(run.exit_code, 0) << run.err;
    EXPECT_TRUE(Contains(run.out, "sheet-fresnel")) << run.out;
    EXPECT_TRUE(Contains(run.out, "Au, Cu")) << run.out;
    EXPECT_TRUE(Contains(run.out, "load-equirect")) << run.out;
    EXPECT_TRUE(Contains(run.out, "sheet.png")) << run.out;
    EXPECT_FALSE(Contains(run.out, "cpu-reference")) << run.out;  // the scene's own plan has it; the sheet does not
    EXPECT_FALSE(fs::exists(dir.path() / "out"));
}

TEST(PreviewCli, SheetFilesAreRelativeToTheCurrentFolderNotTheScenes) {
    TempDir dir;
    fs::create_directories(dir.path() / "scenes");
    const fs::path scene = dir.write("scenes/sheet.json", R"({"image": {"width": 32, "height": 32},
        "spheres": [{"center": [0, 1, 0], "radius": 0.5, "reflection": "classic"}]})");
    fs::copy_file(kFixtures / "valid-nk.csv", dir.path() / "my-gold.csv");
    // Run in dir: "my-gold.csv" is there, not beside the scene.
    const fs::path previous = fs::current_path();
    fs::current_path(dir.path());
    const CommandRun explained = glpreview(scene.string() + " --sheet my-gold.csv --explain", dir);
    const CommandRun rendered = glpreview(scene.string() + " --sheet my-gold.csv -o out", dir);
    fs::current_path(previous);
    EXPECT_EQ(explained.exit_code, 0) << explained.err;
    EXPECT_TRUE(Contains(explained.out, (dir.path() / "my-gold.csv").string())) << explained.out;
    ASSERT_EQ(rendered.exit_code, 0) << rendered.err;
    EXPECT_TRUE(fs::exists(dir.path() / "out" / "sheet.json"));
}

// A scene named by a path relative to the working folder finds its image and material files beside it (each
// resolved against the scene's folder once, not twice).
TEST(PreviewCli, ARelativeScenePathFindsTheFilesBesideTheScene) {
    TempDir dir;
    fs::create_directories(dir.path() / "scenes");
    fs::copy_file(kData / "scenes" / "sky.hdr", dir.path() / "scenes" / "sky.hdr");
    fs::copy_file(kFixtures / "valid-nk.csv", dir.path() / "scenes" / "my-gold.csv");
    dir.write("scenes/sky.json", R"({"image": {"width": 24, "height": 16},
        "environment": {"type": "equirect", "file": "sky.hdr"},
        "spheres": [{"center": [0, 1, 0], "radius": 0.5, "reflection": "classic", "material": "my-gold.csv"}],
        "outputs": {"png": false, "difference": false}})");
    const fs::path previous = fs::current_path();
    fs::current_path(dir.path());
    const CommandRun rendered = glpreview("scenes/sky.json -o out", dir);
    fs::current_path(previous);
    ASSERT_EQ(rendered.exit_code, 0) << rendered.err;
    EXPECT_TRUE(fs::exists(dir.path() / "out" / "beauty.exr"));
}

TEST(PreviewCli, TheSheetsLightColumnShowsTheHighlightAndNeedsARoom) {
    TempDir dir;
    const std::string scene = (kData / "scenes" / "sheet.json").string();
    const CommandRun run = glpreview(scene + " --sheet Au --sheet-models f82-tint --sheet-light on --size 64x64 -o " +
                                         (dir.path() / "out").string(),
                                     dir);
    ASSERT_EQ(run.exit_code, 0) << run.err;
    std::ifstream in(dir.path() / "out" / "sheet.json");
    const auto sheet = nlohmann::json::parse(in);
    ASSERT_TRUE(sheet.is_array());  // a row per material, model and roughness
    ASSERT_EQ(sheet.size(), 2u);    // the scene's roughness 0 and the lit column
    int lit = 0;
    for (const auto& row : sheet)
        if (row.contains("light")) {
            ++lit;
            EXPECT_DOUBLE_EQ(row["roughness"].get<double>(), 0.35);
        }
    EXPECT_EQ(lit, 1);
    const CommandRun sky =
        glpreview((kData / "scenes" / "sky.json").string() + " --sheet Au --sheet-light on --size 32x32 -o " +
                      (dir.path() / "out2").string(),
                  dir);
    EXPECT_EQ(sky.exit_code, 2);
    EXPECT_TRUE(Contains(sky.err, "--sheet-light: the light column needs a room environment")) << sky.err;
    EXPECT_FALSE(fs::exists(dir.path() / "out2"));
}

TEST(PreviewCli, AFullStdoutIsAnError) {
    // issue 13, item 5: what glpreview prints must reach stdout, or it says so and fails
    TempDir dir;
    const fs::path scene = dir.write("s.json", R"({"spheres": [{"center": [0, 1, 0], "reflection": "classic"}]})");
    const std::string command = "env OCIO= '" + std::string(kGlpreviewExe) + "' '" + scene.string() +
                                "' --explain >/dev/full 2>'" + (dir.path() / "err").string() + "'";
    const int status = std::system(command.c_str());
    ASSERT_TRUE(WIFEXITED(status));
    EXPECT_EQ(WEXITSTATUS(status), 3);
    EXPECT_TRUE(read_file(dir.path() / "err").starts_with("glpreview: cannot write to standard output"));
}

// issue 13, items 7 and 8: an image header is checked before any pixel is allocated; special files are refused
TEST(PreviewImageInput, HostileHeadersAndSpecialFilesAreBadInputNotMemoryOrAHang) {
    TempDir dir;
    const auto message_of = [](const fs::path& file) -> std::string {
        try {
            metalfit::glpreview::read_image(file);
        } catch (const metalfit::InputError& e) {
            return e.what();
        }
        return "";
    };
    const fs::path huge =
        dir.write("huge.hdr", "#?RADIANCE\nFORMAT=32-bit_rle_rgbe\n\n-Y 20000 +X 20000\n" + std::string(200, '\x02'));
    const std::string h = message_of(huge);
    EXPECT_TRUE(h.starts_with(huge.string() + ": ")) << h;
    EXPECT_TRUE(Contains(h, "20000 x 20000")) << h;
    const fs::path negative = dir.write("neg.hdr", "#?RADIANCE\nFORMAT=32-bit_rle_rgbe\n\n-Y -5 +X 20\n");
    const std::string n = message_of(negative);
    EXPECT_TRUE(n.starts_with(negative.string() + ": ")) << n;
    const fs::path fifo = dir.path() / "sky.exr";
    ASSERT_EQ(::mkfifo(fifo.c_str(), 0600), 0);
    EXPECT_EQ(message_of(fifo), fifo.string() + ": cannot read the image: not a regular file");
    EXPECT_EQ(message_of("/dev/zero"), "/dev/zero: cannot read the image: not a regular file");
}

}  // namespace test_preview_cli
}  // namespace metalfit::test
