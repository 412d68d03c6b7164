// `metalfit bench` end to end: the JSON schema (metalfit.bench/1), the Markdown page, the GPU sections from a fake
// glpreview (a test script, never a product path). Times are never asserted.
#include <algorithm>
#include <gtest/gtest.h>

#include <sys/stat.h>

#include <nlohmann/json.hpp>

#include "libfit/models/model.hpp"
#include "metalfit_bench/bench_report.hpp"
#include "test_support.hpp"

namespace test_cli_bench {

using metalfit::test::read_file;
using metalfit::test::TempDir;
using nlohmann::json;

using Result = metalfit::test::CommandResult;

Result run(const TempDir& dir, const std::string& args) {
    return metalfit::test::run_command(metalfit::test::kMetalfitExe, args, dir.path());
}

void expect_number(const json& j, const char* key) { EXPECT_TRUE(j.at(key).is_number()) << key << " in " << j.dump(); }
void expect_number_or_null(const json& j, const char* key) {
    EXPECT_TRUE(j.at(key).is_number() || j.at(key).is_null()) << key << " in " << j.dump();
}

TEST(CliBench, QuickJsonFollowsTheSchemaAndWritesTheMarkdownPage) {
    TempDir dir;
    const auto fake = dir.write("glpreview", R"(#!/bin/sh
case "$1" in
--bench-shaders) echo '{"renderer": "fake", "size": [1024, 1024], "frames": 10, "models": [
  {"model": "schlick", "ms_per_frame": 1.0, "ratio_to_conductor_rgb": 0.25},
  {"model": "conductor-rgb", "ms_per_frame": 4.0, "ratio_to_conductor_rgb": 1.0},
  {"model": "reference-lut", "ms_per_frame": 2.0, "ratio_to_conductor_rgb": 0.5}]}' ;;
*) echo 'glpreview: localization not built' >&2; exit 3 ;;
esac
)");
    chmod(fake.c_str(), 0755);
    const auto page = dir.write("page.md", std::string("old\n") + metalfit::bench::kReadingBegin + "\nMy reading.\n" +
                                               metalfit::bench::kReadingEnd + "\n");
    const Result r =
        run(dir, "bench --quick --json --glpreview '" + fake.string() + "' --markdown '" + page.string() + "'");
    ASSERT_EQ(r.exit_code, 0) << r.err;
    const json j = json::parse(r.out);
    EXPECT_EQ(j.at("schema"), "metalfit.bench/1");
    EXPECT_EQ(j.at("quick"), true);
    EXPECT_EQ(j.at("material"), "Au");
    EXPECT_EQ(j.at("catalog_materials"), metalfit::test::catalog_material_count());
    for (const char* key : {"cpu", "os", "compiler", "build_type"})
        EXPECT_TRUE(j.at("machine").at(key).is_string()) << key;
    EXPECT_TRUE(j.at("machine").at("cores").is_number_integer());

    const json& rows = j.at("rows");
    // A row per registered model, then exact-complex, exact-real, two LUTs and the spectral reference.
    ASSERT_EQ(rows.size(), metalfit::all_models().size() + 5);
    std::map<std::string, json> by_id;
    for (const json& row : rows) {
        by_id[row.at("id")] = row;
        for (const char* key : {"ns_per_eval_scalar", "ns_per_eval_array", "ratio_scalar", "ratio_scalar_noise",
                                "ratio_array", "ratio_array_noise"})
            expect_number(row, key);
        for (const char* key : {"median_rel_rms", "worst_rel_rms", "params_per_channel", "fit_ms_per_material",
                                "spirv_ops", "shader_ratio"})
            expect_number_or_null(row, key);
        EXPECT_TRUE(row.at("pareto").at("models").at("cpu").is_boolean());
        EXPECT_TRUE(row.at("pareto").at("all").at("cpu").is_boolean());
        EXPECT_GT(row.at("ns_per_eval_scalar").get<double>(), 0);
    }
    // Definitions, not timings: the baseline's ratio to itself is 1; accuracy comes from the catalog fits.
    EXPECT_EQ(by_id.at("conductor-rgb").at("ratio_scalar"), 1.0);
    EXPECT_EQ(by_id.at("schlick").at("params_per_channel"), 1);
    // The worst catalog material of Schlick is the one `metalfit fit --all` reports (worst channel, over materials).
    const Result catalog_fit = run(dir, "fit --all --model schlick --json");
    ASSERT_EQ(catalog_fit.exit_code, 0) << catalog_fit.err;
    double worst = 0.0;
    const json record = json::parse(catalog_fit.out);
    for (const auto& [id, material] : record.at("materials").items())
        for (const json& channel : material.at("models").at("schlick").at("fit").at("metrics").at("rel_rms"))
            worst = std::max(worst, channel.get<double>());
    ASSERT_GT(worst, 0.0);
    EXPECT_NEAR(by_id.at("schlick").at("worst_rel_rms").get<double>(), worst, 1e-6 + 1e-4 * worst);
    EXPECT_EQ(by_id.at("spectral-reference").at("median_rel_rms"), 0.0);
    EXPECT_EQ(by_id.at("exact-complex").at("median_rel_rms"), by_id.at("conductor-rgb").at("median_rel_rms"));
    EXPECT_EQ(by_id.at("schlick").at("shader_ratio"), 0.25);
    EXPECT_EQ(by_id.at("lut-64").at("shader_ratio"), 0.5);
    EXPECT_TRUE(by_id.at("gulbrandsen").at("shader_ratio").is_null());
    int front = 0;
    for (const json& row : rows) front += row.at("pareto").at("models").at("cpu").get<bool>();
    EXPECT_GE(front, 1);
    EXPECT_EQ(by_id.at("lut-64").at("pareto").at("models").at("cpu"), false);  // not a model

    const json& gpu = j.at("gpu");
    EXPECT_EQ(gpu.at("shaders").at("result").at("renderer"), "fake");
    EXPECT_TRUE(gpu.at("shaders").at("skipped").is_null());
    EXPECT_TRUE(gpu.at("localization").at("result").is_null());
    EXPECT_EQ(gpu.at("localization").at("skipped"),
              "glpreview --bench-localization failed (exit 3): glpreview: localization not built");
    EXPECT_EQ(j.at("convergence").at("rows").size(), 7u);
    EXPECT_EQ(j.at("thesis_table_3_2").size(), 3u);

    const std::string md = read_file(page);
    EXPECT_NE(md.find("Generated by `metalfit bench --quick --markdown "), std::string::npos);
    EXPECT_NE(md.find("My reading."), std::string::npos);
    EXPECT_EQ(md.find("old\n"), std::string::npos);
    EXPECT_NE(md.find("| spectral-reference |"), std::string::npos);
    EXPECT_NE(md.find("GPU localization section skipped: glpreview --bench-localization failed"), std::string::npos);
}

TEST(CliBench, UnknownMaterialIsAUsageError) {
    TempDir dir;
    const Result r = run(dir, "bench --quick --material unobtainium");
    EXPECT_EQ(r.exit_code, 2);
    EXPECT_TRUE(r.out.empty());
    EXPECT_EQ(std::count(r.err.begin(), r.err.end(), '\n'), 1) << r.err;
}

}  // namespace test_cli_bench
