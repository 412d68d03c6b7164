// The glossy method chosen from the measured table (issue 36 item 4): the rule on tables made up for it, the table
// glpreview is built with against data/glossy-choice.json, and the scene, --explain and the sheet using the choice.
#include <gtest/gtest.h>

#include <fstream>
#include <sstream>

#include <nlohmann/json.hpp>

#include "glpreview/render/plan.hpp"
#include "glpreview/render/sphere_sheet.hpp"
#include "glpreview/scene/glossy_choice.hpp"
#include "glpreview/scene/scene.hpp"
#include "libfit/base/errors.hpp"
#include "libfit/base/number_text.hpp"
#include "test_support.hpp"

namespace metalfit::glpreview {
namespace test_preview_glossy_choice {

using test::kData;
using Json = nlohmann::json;

struct Row {
    double roughness;
    int spheres, wins;
    double median, worst;
};

std::string table_text(const std::vector<Row>& rows) {
    Json j{{"schema", "metalfit.glossy-choice/1"}, {"command", "made up"}, {"rows", Json::array()}};
    for (const Row& r : rows)
        j["rows"].push_back({{"roughness", r.roughness},
                             {"spheres", r.spheres},
                             {"localized_wins", r.wins},
                             {"median_ratio", r.median},
                             {"worst_ratio", r.worst}});
    return j.dump();
}

// Localized wins three spheres in four at 0.3 (an isolated row the rule must not take), only a majority at 0.5, three
// in four from 0.7 on; its worst ratio is above kLocalizedWorstRatio (4) at 0.4 and below, except at 0.3.
const std::vector<Row> kRows{{0.1, 10, 0, 4.0, 50.0}, {0.3, 8, 6, 0.9, 2.5},   {0.4, 10, 3, 1.3, 4.5},
                             {0.5, 10, 6, 0.9, 3.5},  {0.7, 10, 8, 0.95, 1.2}, {0.9, 10, 9, 0.8, 1.1}};

TEST(PreviewGlossyChoice, TheRuleTakesTheRangeAtTheTopWhereLocalizedWinsAndWorks) {
    const GlossyChoiceTable table = parse_glossy_choice_table(table_text(kRows), "t.json");
    ASSERT_TRUE(table.localized_from);
    EXPECT_EQ(*table.localized_from, 0.7);
    ASSERT_TRUE(table.localized_works_from);
    EXPECT_EQ(*table.localized_works_from, 0.5);

    EXPECT_EQ(choose_glossy_method(0.69, GlossyRequest::automatic, table).method, GlossyMethod::prefiltered);
    EXPECT_EQ(choose_glossy_method(0.3, GlossyRequest::automatic, table).method, GlossyMethod::prefiltered);
    EXPECT_EQ(choose_glossy_method(0.7, GlossyRequest::automatic, table).method, GlossyMethod::localized);
    EXPECT_EQ(choose_glossy_method(1.0, GlossyRequest::automatic, table).method, GlossyMethod::localized);
    // Asked for: prefiltered always; localized where it works, else prefiltered, saying so.
    EXPECT_EQ(choose_glossy_method(1.0, GlossyRequest::prefiltered, table).method, GlossyMethod::prefiltered);
    const GlossyChoice works = choose_glossy_method(0.5, GlossyRequest::localized, table);
    EXPECT_EQ(works.method, GlossyMethod::localized);
    EXPECT_FALSE(works.fell_back);
    const GlossyChoice fails = choose_glossy_method(0.45, GlossyRequest::localized, table);
    EXPECT_EQ(choose_glossy_method(0.3, GlossyRequest::localized, table).method, GlossyMethod::prefiltered);
    EXPECT_EQ(fails.method, GlossyMethod::prefiltered);
    EXPECT_TRUE(fails.fell_back);
    EXPECT_TRUE(test::Contains(fails.reason, "'localized' fails at roughness 0.45"));
    EXPECT_TRUE(test::Contains(fails.reason, "from roughness 0.5 on"));
    EXPECT_TRUE(test::Contains(fails.reason, "rendered 'prefiltered'"));
    EXPECT_EQ(fails.reason.find('\n'), std::string::npos);
}

TEST(PreviewGlossyChoice, ATableWhereLocalizedNeverWinsOrWorksKeepsPrefiltered) {
    const GlossyChoiceTable table =
        parse_glossy_choice_table(table_text({{0.2, 5, 0, 3.0, 9.0}, {0.8, 5, 3, 0.95, 4.4}}), "t.json");
    EXPECT_FALSE(table.localized_from);
    EXPECT_FALSE(table.localized_works_from);
    EXPECT_EQ(choose_glossy_method(1.0, GlossyRequest::automatic, table).method, GlossyMethod::prefiltered);
    const GlossyChoice asked = choose_glossy_method(1.0, GlossyRequest::localized, table);
    EXPECT_TRUE(asked.fell_back);
    EXPECT_TRUE(test::Contains(asked.reason, "at every measured roughness"));
}

TEST(PreviewGlossyChoice, ABadTableIsRefusedNamingTheField) {
    auto error = [](const std::string& text) -> std::string {
        try {
            parse_glossy_choice_table(text, "t.json");
        } catch (const InputError& e) {
            return e.what();
        }
        return "no error";
    };
    EXPECT_TRUE(test::Contains(error("{"), "t.json"));
    EXPECT_TRUE(test::Contains(error(R"({"schema": "other", "rows": []})"), "t.json: schema"));
    EXPECT_TRUE(test::Contains(error(table_text({})), "t.json: rows: expected a non-empty array"));
    EXPECT_TRUE(test::Contains(error(table_text({{0.4, 5, 1, 1, 1}, {0.4, 5, 1, 1, 1}})),
                               "t.json: rows[1].roughness: rows must be by increasing roughness"));
    EXPECT_TRUE(test::Contains(error(table_text({{0.4, 5, 6, 1, 1}})), "t.json: rows[0].localized_wins"));
    EXPECT_TRUE(test::Contains(error(table_text({{1.5, 5, 1, 1, 1}})), "t.json: rows[0].roughness: must be in (0, 1]"));
    Json no_ratio = Json::parse(table_text({{0.4, 5, 1, 1, 1}}));
    no_ratio["rows"][0].erase("worst_ratio");
    EXPECT_TRUE(test::Contains(error(no_ratio.dump()), "t.json: rows[0].worst_ratio: expected a number"));
}

// The table built in is the data file's, and its rows are what the measuring script writes.
TEST(PreviewGlossyChoice, TheBuiltInTableIsTheDataFile) {
    std::ifstream in(kData / "glossy-choice.json");
    ASSERT_TRUE(in) << "data/glossy-choice.json";
    std::stringstream text;
    text << in.rdbuf();
    const GlossyChoiceTable file = parse_glossy_choice_table(text.str(), "data/glossy-choice.json");
    const GlossyChoiceTable& built_in = glossy_choice_table();
    ASSERT_EQ(file.rows.size(), built_in.rows.size());
    for (std::size_t i = 0; i < file.rows.size(); ++i) {
        EXPECT_EQ(file.rows[i].roughness, built_in.rows[i].roughness);
        EXPECT_EQ(file.rows[i].localized_wins, built_in.rows[i].localized_wins);
        EXPECT_EQ(file.rows[i].worst_ratio, built_in.rows[i].worst_ratio);
    }
    EXPECT_EQ(file.localized_from, built_in.localized_from);
    EXPECT_EQ(file.localized_works_from, built_in.localized_works_from);
    // The rows summarise the per-sphere figures kept beside them.
    const Json j = Json::parse(text.str());
    for (const Json& row : j.at("rows")) {
        int spheres = 0, wins = 0;
        double worst = 0;
        for (const Json& s : j.at("spheres"))
            if (s.at("roughness") == row.at("roughness")) {
                ++spheres;
                const double ratio = s.at("localized_rmse").get<double>() / s.at("prefiltered_rmse").get<double>();
                if (ratio < 1) ++wins;
                worst = std::max(worst, ratio);
            }
        EXPECT_EQ(spheres, row.at("spheres").get<int>());
        EXPECT_EQ(wins, row.at("localized_wins").get<int>());
        EXPECT_DOUBLE_EQ(worst, row.at("worst_ratio").get<double>());
    }
}

// A scene's spheres get the built-in table's choice; a localized sphere where it fails is rendered prefiltered with a
// warning naming the field, and --explain says why each rough sphere got its method.
TEST(PreviewGlossyChoice, TheSceneAndTheExplanationFollowTheBuiltInTable) {
    const GlossyChoiceTable& table = glossy_choice_table();
    ASSERT_TRUE(table.localized_works_from) << "the measured table: localized works at high roughness";
    const double works = *table.localized_works_from;
    const double below = works - 0.05;
    const std::string json = R"({"spheres": [{"center": [0, 1, 0], "roughness": )" + std::to_string(below) +
                             R"(, "glossy": "localized"}, {"center": [1, 1, 0], "roughness": )" +
                             std::to_string(works) +
                             R"(, "glossy": "localized"}, {"center": [-1, 1, 0], "roughness": 0.1},
                             {"center": [2, 1, 0], "roughness": 1.0, "glossy": "auto"}]})";
    const Scene scene = parse_scene(json, "s.json");
    EXPECT_EQ(scene.spheres[0].glossy, GlossyMethod::prefiltered);
    EXPECT_EQ(scene.spheres[0].glossy_request, GlossyRequest::localized);
    EXPECT_EQ(scene.spheres[1].glossy, GlossyMethod::localized);
    EXPECT_EQ(scene.spheres[2].glossy_request, GlossyRequest::automatic);  // the default
    EXPECT_EQ(scene.spheres[2].glossy, choose_glossy_method(0.1, GlossyRequest::automatic).method);
    EXPECT_EQ(scene.spheres[3].glossy, table.localized_from && *table.localized_from <= 1.0
                                           ? GlossyMethod::localized
                                           : GlossyMethod::prefiltered);
    int fallbacks = 0;
    for (const std::string& w : scene.warnings)
        if (test::Contains(w, "s.json: spheres[0].glossy: 'localized' fails at roughness")) ++fallbacks;
    EXPECT_EQ(fallbacks, 1);
    const std::string explained = explain(build_plan(scene), scene);
    EXPECT_TRUE(test::Contains(explained, "sphere 0 (roughness " + significant_text(below, 3) +
                                              ", 'localized'): prefiltered: 'localized' fails"));
    EXPECT_TRUE(test::Contains(
        explained, "sphere 2 (roughness 0.1, 'auto'): " + std::string(to_string(scene.spheres[2].glossy)) + ": auto:"));
    // --glossy-as-asked (measuring the table): localized wherever asked, and the fallback's warning gone.
    Scene as_asked = scene;
    honour_glossy_requests(as_asked);
    EXPECT_EQ(as_asked.spheres[0].glossy, GlossyMethod::localized);
    EXPECT_EQ(as_asked.spheres[2].glossy, scene.spheres[2].glossy);
    EXPECT_EQ(as_asked.warnings.size() + 1, scene.warnings.size());
    // The plan runs what the chosen methods need, and nothing for a method not chosen.
    const Plan plan = build_plan(scene);
    EXPECT_TRUE(plan.runs("prefilter-environment"));
    EXPECT_TRUE(plan.runs("downsample-environment 8"));
}

// The sheet's columns each get the method of their roughness: where auto picks localized at the top, a sheet with a
// column on each side of the switch plans both the prefilter and the downsample.
TEST(PreviewGlossyChoice, TheSheetPlansEachColumnsMethod) {
    const GlossyChoiceTable& table = glossy_choice_table();
    ASSERT_TRUE(table.localized_from) << "the measured table: localized wins at high roughness";
    const Scene scene = load_scene(kData / "scenes" / "sheet.json");
    SheetRequest request{{"Au"}, {"schlick"}, {0.0, 0.2}, false, false, "", ""};
    Plan plan = build_sheet_plan(scene, request);
    EXPECT_TRUE(plan.runs("prefilter-environment"));
    EXPECT_FALSE(plan.runs("downsample-environment 8"));
    request.roughness = {0.2, *table.localized_from};
    plan = build_sheet_plan(scene, request);
    EXPECT_TRUE(plan.runs("prefilter-environment"));
    EXPECT_TRUE(plan.runs("downsample-environment 8"));
}

}  // namespace test_preview_glossy_choice
}  // namespace metalfit::glpreview
