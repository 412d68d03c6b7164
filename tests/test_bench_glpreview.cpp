// The GPU sections of `metalfit bench`: parsing glpreview's JSON, and skipping with a reason when it is missing or
// fails. The fake glpreview here is a test script, never a product path.
#include <gtest/gtest.h>

#include <sys/stat.h>

#include "metalfit_bench/bench_report.hpp"
#include "metalfit_bench/glpreview_results.hpp"
#include "test_support.hpp"

namespace test_bench_glpreview {

using namespace metalfit::bench;
using metalfit::test::TempDir;
using nlohmann::json;

const char* kShaders =
    R"({"renderer": "fake GL", "size": [1024, 1024], "frames": 60, "evaluations_per_pixel": 16, "models": [
  {"model": "schlick", "ms_per_frame": 0.25, "ratio_to_conductor_rgb": 0.5},
  {"model": "conductor-rgb", "ms_per_frame": 0.5, "ratio_to_conductor_rgb": 1.0},
  {"model": "reference-lut", "ms_per_frame": 0.3, "ratio_to_conductor_rgb": 0.6}]})";

const char* kLocalization = R"({"renderer": "fake GL", "size": [700, 700], "rooms": [{"room": "difficult", "rows": [
  {"mode": "classic", "strategy": null, "iterations": 0, "search_steps": 0, "tolerance": null, "mean_iterations": 0.0, "ms_per_frame": 1.0, "ratio_to_classic": 1.0, "ratio_noise": 0.0, "rmse": 0.2, "mean_abs": 0.1},
  {"mode": "distance-impostor", "strategy": "illinois", "iterations": 8, "search_steps": 8, "tolerance": 0.0001, "mean_iterations": 3.5, "ms_per_frame": 2.0, "ratio_to_classic": 2.0, "ratio_noise": 0.25, "rmse": 0.01, "mean_abs": 0.005}]}]})";

TEST(GlpreviewResults, ParsesTheShaderContract) {
    const ShaderBench b = parse_shader_bench(json::parse(kShaders));
    EXPECT_EQ(b.renderer, "fake GL");
    EXPECT_EQ(b.width, 1024);
    EXPECT_EQ(b.frames, 60);
    EXPECT_EQ(b.evaluations_per_pixel, 16);
    ASSERT_EQ(b.models.size(), 3u);
    ASSERT_NE(b.find("schlick"), nullptr);
    EXPECT_DOUBLE_EQ(b.find("schlick")->ratio_to_conductor_rgb, 0.5);
    EXPECT_EQ(b.find("gulbrandsen"), nullptr);
    EXPECT_EQ(to_json(b), json::parse(kShaders));  // round trip
}

TEST(GlpreviewResults, ParsesTheLocalizationContract) {
    const LocalizationBench b = parse_localization_bench(json::parse(kLocalization));
    ASSERT_EQ(b.rooms.size(), 1u);
    ASSERT_EQ(b.rooms[0].rows.size(), 2u);
    EXPECT_EQ(b.rooms[0].rows[0].strategy, std::nullopt);
    EXPECT_EQ(b.rooms[0].rows[1].strategy, "illinois");
    EXPECT_EQ(b.rooms[0].rows[1].iterations, 8);
    EXPECT_EQ(b.rooms[0].rows[1].search_steps, 8);
    EXPECT_DOUBLE_EQ(b.rooms[0].rows[1].mean_iterations, 3.5);
    EXPECT_DOUBLE_EQ(b.rooms[0].rows[1].ratio_noise, 0.25);
    EXPECT_EQ(b.rooms[0].rows[0].tolerance, std::nullopt);
    EXPECT_EQ(to_json(b), json::parse(kLocalization));
}

TEST(GlpreviewResults, SchemaErrorsNameTheField) {
    json j = json::parse(kShaders);
    j["models"][1].erase("ms_per_frame");
    try {
        parse_shader_bench(j);
        FAIL() << "no error";
    } catch (const std::runtime_error& e) {
        EXPECT_EQ(std::string(e.what()), "models[1].ms_per_frame: missing");
    }
    json l = json::parse(kLocalization);
    l["rooms"][0]["rows"][0]["strategy"] = 3;
    EXPECT_THROW(parse_localization_bench(l), std::runtime_error);
    json s = json::parse(kShaders);
    s["size"] = {1024};
    EXPECT_THROW(parse_shader_bench(s), std::runtime_error);
}

std::filesystem::path script(const TempDir& dir, const std::string& body) {
    const auto path = dir.write("glpreview", "#!/bin/sh\n" + body);
    chmod(path.c_str(), 0755);
    return path;
}

TEST(GlpreviewResults, MissingOrFailingGlpreviewIsSkippedWithAReason) {
    const auto missing = run_shader_bench("/nonexistent/glpreview", true);
    EXPECT_FALSE(missing.value);
    EXPECT_EQ(missing.skipped, "no glpreview executable at /nonexistent/glpreview");

    TempDir dir;
    const auto failing = script(dir, "echo 'glpreview: no EGL display' >&2\nexit 4\n");
    const auto failed = run_localization_bench(failing, false);
    EXPECT_FALSE(failed.value);
    EXPECT_EQ(failed.skipped, "glpreview --bench-localization failed (exit 4): glpreview: no EGL display");

    const auto garbage = script(dir, "echo 'not json'\n");
    const auto unusable = run_shader_bench(garbage, false);
    EXPECT_FALSE(unusable.value);
    EXPECT_NE(unusable.skipped.find("unusable JSON"), std::string::npos) << unusable.skipped;
}

TEST(GlpreviewResults, PassesQuickAndJsonAndReadsStdout) {
    TempDir dir;
    // Prints the contract only when called with exactly the expected arguments.
    const auto fake = script(dir, std::string("if [ \"$*\" = '--bench-shaders --quick --json' ]; then cat <<'EOF'\n") +
                                      kShaders + "\nEOF\nelse echo \"unexpected arguments: $*\" >&2; exit 2; fi\n");
    const auto section = run_shader_bench(fake, true);
    ASSERT_TRUE(section.value) << section.skipped;
    EXPECT_EQ(section.value->models.size(), 3u);
    EXPECT_FALSE(run_shader_bench(fake, false).value);
}

TEST(BenchMarkdown, KeepsTheHandWrittenReading) {
    BenchReport report;
    report.command_line = "metalfit bench --markdown page.md";
    report.material = "Au";
    const std::string fresh = to_markdown(report, "");
    EXPECT_NE(fresh.find(kReadingBegin), std::string::npos);
    EXPECT_NE(fresh.find("No reading written yet"), std::string::npos);
    EXPECT_NE(fresh.find("Generated by `metalfit bench --markdown page.md`"), std::string::npos);
    const std::string previous = "# old page\n\n| stale | table |\n\n" + std::string(kReadingBegin) +
                                 "\nSchlick is cheap.\n\nSecond paragraph.\n" + kReadingEnd + "\n";
    const std::string again = to_markdown(report, previous);
    EXPECT_NE(again.find(std::string(kReadingBegin) + "\nSchlick is cheap.\n\nSecond paragraph.\n" + kReadingEnd),
              std::string::npos)
        << again;
    EXPECT_EQ(again.find("stale"), std::string::npos);
    EXPECT_EQ(again.find("No reading written yet"), std::string::npos);
    EXPECT_EQ(to_markdown(report, again), again);  // regeneration is a fixed point
}

}  // namespace test_bench_glpreview
