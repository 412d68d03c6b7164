// glpreview --bench-glossy (issue 17 item 4): the table's shape, and its RMSE column is what a preview of the same
// scene writes into metrics.json (no timing asserts: the ratios are measured, never checked).
#include <gtest/gtest.h>

#include <set>

#include "glpreview/gl/gl_context.hpp"
#include "glpreview/render/gpu_bench.hpp"
#include "glpreview/render/preview.hpp"
#include "test_support.hpp"

namespace metalfit::glpreview {
namespace test_preview_glossy_bench {

using test::kData;

TEST(PreviewGlossyBench, TheTableHasEveryRoughnessAndMethodAndItsRmseIsThePreviewsMetric) {
    GlContext context = GlContext::create();
    const PreviewOptions options{kData, choose_ocio_config(std::nullopt, kData), {}, 0};
    const nlohmann::ordered_json result = bench_glossy(context, options, true);
    const auto& rows = result.at("rows");
    const std::vector<GlossyVariant> variants = glossy_bench_variants();
    ASSERT_EQ(rows.size(), 1 + 5 * 5u);  // the mirror classic pass, then 5 roughness values × 5 methods
    ASSERT_EQ(rows.size(), variants.size());
    EXPECT_EQ(rows[0].at("method"), "mirror classic");
    EXPECT_EQ(rows[0].at("ratio_to_mirror_classic").get<double>(), 1.0);
    std::set<std::pair<double, std::string>> cells;
    for (std::size_t i = 1; i < rows.size(); ++i) {
        cells.insert({rows[i].at("roughness").get<double>(), rows[i].at("method").get<std::string>()});
        EXPECT_GT(rows[i].at("ms_per_frame").get<double>(), 0);
        EXPECT_GT(rows[i].at("ratio_to_mirror_classic").get<double>(), 0);
        EXPECT_GT(rows[i].at("rmse").get<double>(), 0);
    }
    for (double r : {0.05, 0.1, 0.2, 0.4, 0.8})
        for (const char* m : {"prefiltered box-parallax", "prefiltered distance-impostor", "localized M=2",
                              "localized M=4", "localized M=8"})
            EXPECT_TRUE(cells.count({r, m})) << r << " " << m;
    EXPECT_EQ(cells.size(), 25u);
    ASSERT_EQ(result.at("mirror_scenes").size(), 5u);
    for (const auto& m : result.at("mirror_scenes")) EXPECT_GT(m.at("ms_per_frame").get<double>(), 0);

    // The RMSE column: a preview of the same scene (its own capture, prefilter or downsample, its own Monte-Carlo
    // reference) writes the same number into metrics.json — the mirror row against the analytic reference.
    for (std::size_t i : {std::size_t{0}, std::size_t{1}, std::size_t{2}, std::size_t{9}, std::size_t{25}}) {
        const GlossyVariant& v = variants[i];
        Scene scene = glossy_bench_scene(kData, true, v);
        scene.outputs.png = scene.outputs.exr = false;
        scene.outputs.beauty = scene.outputs.reference = scene.outputs.difference = false;
        const PreviewResult preview = run_preview(scene, options, &context);
        ASSERT_FALSE(preview.metrics.is_null());
        const auto& sphere = preview.metrics.at("spheres").at(0);
        EXPECT_EQ(sphere.at("roughness").get<double>(), v.roughness);
        EXPECT_NEAR(sphere.at("rmse").get<double>(), rows[i].at("rmse").get<double>(), 1e-12)
            << glossy_variant_name(v) << " " << v.roughness;
        EXPECT_NEAR(sphere.at("mean_abs").get<double>(), rows[i].at("mean_abs").get<double>(), 1e-12) << i;
        EXPECT_NEAR(sphere.at("reference_noise").get<double>(), rows[i].at("reference_noise").get<double>(), 1e-12)
            << i;
    }
}

}  // namespace test_preview_glossy_bench
}  // namespace metalfit::glpreview
