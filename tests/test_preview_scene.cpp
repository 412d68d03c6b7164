// glpreview without GL: strict scene parsing, the plan (features and culled passes), the CPU environment tracer.
#include <gtest/gtest.h>
#include <sys/stat.h>

#include <algorithm>
#include <cmath>
#include <numbers>
#include <set>

#include "glpreview/render/environment.hpp"
#include "glpreview/render/gpu_bench.hpp"
#include "glpreview/render/plan.hpp"
#include "glpreview/scene/confined_file.hpp"
#include "glpreview/scene/scene.hpp"
#include "libfit/base/errors.hpp"
#include "libfit/color/display_transform.hpp"
#include "test_support.hpp"

namespace metalfit::glpreview {
namespace test_preview_scene {

const char* kMinimal = R"({"spheres": [{"center": [0, 1, 0]}]})";

std::string parse_error(const std::string& json) {
    try {
        parse_scene(json, "bad.json");
    } catch (const InputError& e) {
        const std::string what = e.what();
        EXPECT_EQ(what.find('\n'), std::string::npos) << what;
        return what;
    }
    ADD_FAILURE() << "no error for " << json;
    return {};
}

TEST(PreviewScene, DefaultsForAMinimalScene) {
    const Scene scene = parse_scene(kMinimal, "s.json");
    ASSERT_EQ(scene.spheres.size(), 1u);
    EXPECT_EQ(scene.environment.type, EnvironmentType::room);
    EXPECT_TRUE(shows_reference(scene.spheres[0]));
    EXPECT_EQ(scene.spheres[0].reflection, ReflectionMode::distance_impostor);
    EXPECT_EQ(scene.environment.room.panels.size(), 4u);  // the default 2 × 2 ceiling panels
    const Vec3 o = scene.environment.reference();
    EXPECT_DOUBLE_EQ(o.y, 1.5);
}

TEST(PreviewScene, MalformedScenesAreOneLineErrorsNamingTheField) {
    EXPECT_TRUE(test::Contains(parse_error(R"({"spheres": [{"center": [0, 1, 0], "radius": "big"}]})"),
                               "bad.json: spheres[0].radius: expected a number"));
    EXPECT_TRUE(test::Contains(parse_error(R"({"spheres": [{"center": [0, 1, 0], "colour": 1}]})"),
                               "spheres[0].colour: unknown key"));
    EXPECT_TRUE(test::Contains(parse_error(R"({"spheres": [{"center": [0, 1]}]})"),
                               "spheres[0].center: expected an array of 3 numbers"));
    EXPECT_TRUE(test::Contains(
        parse_error(R"({"spheres": [{"center": [0, 1, 0], "strategy": "bisection"}]})"),
        "spheres[0].strategy: unknown value 'bisection' (known: secant, false-position, mixed, illinois, safe-secant)"));
    EXPECT_TRUE(test::Contains(parse_error(R"({"spheres": [{"center": [0, 1, 0], "iterations": 2.5}]})"),
                               "spheres[0].iterations: expected an integer"));
    EXPECT_TRUE(test::Contains(parse_error(R"({"spheres": []})"), "spheres: at least one sphere"));
    EXPECT_TRUE(test::Contains(parse_error(R"({"image": {"width": 0}, "spheres": [{"center": [0,1,0]}]})"),
                               "image.width: must be in [1, 8192]"));
    EXPECT_TRUE(test::Contains(parse_error(R"({"environment": {"type": "cave"}, "spheres": [{"center": [0,1,0]}]})"),
                               "environment.type: unknown value 'cave'"));
    EXPECT_TRUE(test::Contains(
        parse_error(
            R"({"environment": {"boxes": [{"min": [0,0,0], "max": [1,-1,1]}]}, "spheres": [{"center": [0,1,0]}]})"),
        "environment.boxes[0].max: min must be below max"));
    EXPECT_TRUE(test::Contains(
        parse_error(R"({"environment": {"type": "equirect", "file": "sky.exr"}, "spheres": [{"center": [0,1,0]}]})"),
        "spheres[0].reflection: an equirect environment is at infinity"));
    EXPECT_TRUE(test::Contains(
        parse_error(R"({"camera": {"position": [0,1,0], "look_at": [0,2,0]}, "spheres": [{"center": [0,1,0]}]})"),
        "camera.up: is parallel"));
    EXPECT_TRUE(
        test::Contains(parse_error("{\n  \"spheres\": [\n  {\"center\": [0, 1, 0],}\n]}"), "bad.json:3: invalid JSON"));
}

Scene scene_with(const std::string& spheres, const std::string& outputs = "{}", const std::string& environment = "{}") {
    return parse_scene(R"({"environment": )" + environment + R"(, "spheres": )" + spheres + R"(, "outputs": )" +
                           outputs + "}",
                       "s.json");
}

// Issue 18 item 5 and issue 13 items 7–9: numbers beyond double range, limits, warnings, confined paths.
TEST(PreviewScene, ANumberBeyondDoubleRangeNamesTheFileLineAndField) {
    const std::string e = parse_error("{\"spheres\": [{\"center\": [0, 1,\n 1e999]}]}");
    EXPECT_TRUE(test::Contains(e, "bad.json:2: spheres[0].center[2]: number beyond the range of a double")) << e;
    EXPECT_TRUE(test::Contains(parse_error(R"({"image": {"width": 1e309}, "spheres": [{"center": [0, 1, 0]}]})"),
                               "bad.json:1: image.width: number beyond"));
}

TEST(PreviewScene, MessagesQuoteAtMostAShortSanitisedExcerpt) {
    const std::string long_value(5000, 'x');
    const std::string e =
        parse_error(R"({"spheres": [{"center": [0, 1, 0], "strategy": ")" + long_value + "\\u0001\"}]}");
    EXPECT_LT(e.size(), 200u) << e;
    EXPECT_TRUE(test::Contains(e, "unknown value 'xxxx")) << e;
    const std::string key = parse_error("{\"spheres\": [{\"center\": [0, 1, 0], \"\\u001b[31mred\": 1}]}");
    EXPECT_TRUE(test::Contains(key, "spheres[0].\\x1B[31mred: unknown key")) << key;
    const std::string junk = parse_error("{\"spheres\": " + std::string(3000, 'q') + "}");
    EXPECT_LT(junk.size(), 250u) << junk;
    test::TempDir dir;
    EXPECT_THROW(load_scene(dir.path()), InputError);  // a folder, not a regular file
}

TEST(PreviewScene, LimitsOnImageSizeSpheresAndRoomObjects) {
    EXPECT_TRUE(test::Contains(parse_error(R"({"image": {"width": 8193}, "spheres": [{"center": [0, 1, 0]}]})"),
                               "image.width: must be in [1, 8192]"));
    EXPECT_TRUE(
        test::Contains(parse_error(R"({"image": {"width": 8192, "height": 4096}, "spheres": [{"center": [0, 1, 0]}]})"),
                       "image: 8192 x 4096 is more than 16777216 pixels"));
    EXPECT_NO_THROW(
        parse_scene(R"({"image": {"width": 8192, "height": 2048}, "spheres": [{"center": [0, 1, 0]}]})", "s.json"));
    std::string many = R"({"spheres": [)";
    for (std::size_t i = 0; i <= kMaxSpheres; ++i)
        many += std::string(i ? "," : "") + R"({"center": [0, 1, 0], "radius": 0.01})";
    EXPECT_TRUE(test::Contains(parse_error(many + "]}"), "spheres: at most 256 spheres"));
    std::string columns = R"({"environment": {"columns": [)";
    for (std::size_t i = 0; i <= kMaxRoomBoxes; ++i) columns += std::string(i ? "," : "") + R"({"center": [0, 0]})";
    EXPECT_TRUE(test::Contains(parse_error(columns + R"(]}, "spheres": [{"center": [0, 1, 0]}]})"),
                               "environment.columns[32]: at most 32 boxes and columns together"));
    EXPECT_TRUE(test::Contains(
        parse_error(
            R"({"environment": {"type": "sphere-room"}, "spheres": [{"center": [0, 1, 0], "reflection": "box-parallax"}]})"),
        "spheres[0].reflection: box-parallax needs a room environment"));
    EXPECT_TRUE(test::Contains(parse_error(R"({"spheres": [{"center": [0, 1, 0], "tolerance": 2}]})"),
                               "spheres[0].tolerance: must be in [0, 1]"));
}

TEST(PreviewScene, SettingsThatMeanNothingOrLookWrongAreWarnings) {
    const Scene quiet = parse_scene(kMinimal, "s.json");  // the default camera and room: no warning
    EXPECT_TRUE(quiet.warnings.empty());
    const Scene scene = parse_scene(R"({"camera": {"position": [0, 1, 5]},
        "spheres": [{"center": [0, 1, 0], "reflection": "classic", "iterations": 3, "strategy": "secant"},
                    {"center": [2.8, 1, 0]}, {"center": [0, 1, 0], "tolerance": 0.001}]})",
                                    "s.json");
    ASSERT_EQ(scene.warnings.size(), 4u);
    EXPECT_EQ(scene.warnings[0],
              "s.json: spheres[0].strategy: ignored: only the distance impostor refines (reflection 'classic')");
    EXPECT_EQ(scene.warnings[1],
              "s.json: spheres[0].iterations: ignored: only the distance impostor refines (reflection 'classic')");
    EXPECT_EQ(scene.warnings[2], "s.json: camera.position: outside the room (the view shows the walls from behind)");
    EXPECT_TRUE(test::Contains(scene.warnings[3], "s.json: spheres[1]: not inside the room"));
    EXPECT_EQ(scene.spheres[2].tolerance, 0.001);
    EXPECT_EQ(scene.spheres[1].strategy, Strategy::illinois);
    EXPECT_EQ(scene.spheres[1].iterations, 8);
}

TEST(PreviewScene, ScenePathsStayInTheScenesFolderOrTheDatabase) {
    test::TempDir dir;
    std::filesystem::create_directories(dir.path() / "scenes");
    const auto scene_file = dir.write("scenes/s.json", "{}");
    dir.write("outside.csv", "wl,n,k\n500,1,2\n");
    auto scene_with = [&](const std::string& material) {
        return parse_scene(R"({"spheres": [{"center": [0, 1, 0], "material": ")" + material + R"("}]})", scene_file);
    };
    const PathPolicy policy{test::kData, false};
    EXPECT_NO_THROW(confine_scene_paths(scene_with("Au"), policy));                              // a catalog name
    EXPECT_NO_THROW(confine_scene_paths(scene_with("mine.csv"), policy));                        // beside the scene
    EXPECT_NO_THROW(confine_scene_paths(scene_with((test::kData / "x.yml").string()), policy));  // in the database
    for (const std::string& outside :
         {std::string("../outside.csv"), (dir.path() / "outside.csv").string(), std::string("/etc/passwd.csv")}) {
        try {
            confine_scene_paths(scene_with(outside), policy);
            ADD_FAILURE() << outside << " accepted";
        } catch (const InputError& e) {
            EXPECT_TRUE(
                test::Contains(e.what(), "spheres[0].material: a path outside the scene's folder and the database"))
                << e.what();
        }
        EXPECT_NO_THROW(confine_scene_paths(scene_with(outside), PathPolicy{test::kData, true}));
    }
    // A link beside the scene that leads outside is outside.
    std::filesystem::create_symlink(dir.path() / "outside.csv", dir.path() / "scenes" / "link.csv");
    EXPECT_THROW(confine_scene_paths(scene_with("link.csv"), policy), InputError);
    const Scene sky = parse_scene(R"({"environment": {"type": "equirect", "file": "../sky.hdr"},
                                      "spheres": [{"center": [0, 1, 0], "reflection": "classic"}]})",
                                  scene_file);
    EXPECT_THROW(confine_scene_paths(sky, policy), InputError);
}

// The second check, on the open descriptor (ConfinedFile): what the readers read is the file that was checked, even
// when the path is swapped for a link leading outside after the check; a link outside is refused on the descriptor
// itself; a FIFO is refused without waiting for a writer; messages name the scene, the field and the file as given.
TEST(PreviewScene, ScenePathsAreCheckedOnTheOpenDescriptorAndReadThroughIt) {
    test::TempDir dir;
    std::filesystem::create_directories(dir.path() / "scenes");
    const auto scene_file = dir.write("scenes/s.json", "{}");
    dir.write("outside.csv", "outside\n");
    dir.write("scenes/mine.csv", "inside\n");
    const std::optional<PathPolicy> policy = PathPolicy{test::kData, false};
    {
        const ConfinedFile file = ConfinedFile::open(scene_file, policy, "mine.csv", "spheres[0].material");
        EXPECT_EQ(file.original(), dir.path() / "scenes" / "mine.csv");
        EXPECT_EQ(file.path().filename(), "mine.csv");  // readers keep choosing the format by the extension
        // The race: after the check, mine.csv becomes a link to a file outside. The reader still gets the checked file.
        std::filesystem::remove(dir.path() / "scenes" / "mine.csv");
        std::filesystem::create_symlink(dir.path() / "outside.csv", dir.path() / "scenes" / "mine.csv");
        EXPECT_EQ(test::read_file(file.path()), "inside\n");
        EXPECT_EQ(file.in_original_terms("x " + file.path().string() + ":3: bad"),
                  "x " + file.original().string() + ":3: bad");
    }
    // Now mine.csv is a link leading outside: refused on the descriptor, whatever the path looked like.
    try {
        (void)ConfinedFile::open(scene_file, policy, "mine.csv", "spheres[0].material");
        ADD_FAILURE() << "a link leading outside was opened";
    } catch (const InputError& e) {
        EXPECT_TRUE(test::Contains(e.what(), "s.json: spheres[0].material: a path outside the scene's folder"))
            << e.what();
    }
    // Allowed outside, or no policy (library use): read.
    EXPECT_EQ(test::read_file(ConfinedFile::open(scene_file, PathPolicy{test::kData, true}, "mine.csv", "f").path()),
              "outside\n");
    EXPECT_EQ(test::read_file(ConfinedFile::open(scene_file, std::nullopt, "mine.csv", "f").path()), "outside\n");
    // A FIFO beside the scene: refused at once (opening it for reading would wait for a writer), a missing file named.
    ASSERT_EQ(::mkfifo((dir.path() / "scenes" / "pipe.hdr").c_str(), 0600), 0);
    for (const auto& [name, why] :
         {std::pair{"pipe.hdr", "not a regular file"}, std::pair{"missing.hdr", "cannot open it"}}) {
        try {
            (void)ConfinedFile::open(scene_file, policy, name, "environment.file");
            ADD_FAILURE() << name << " opened";
        } catch (const InputError& e) {
            EXPECT_TRUE(test::Contains(
                e.what(), "s.json: environment.file: " + (dir.path() / "scenes" / name).string() + ": " + why))
                << e.what();
        }
    }
}

TEST(PreviewPlan, FeaturesFollowTheScene) {
    Features f = plan_features(scene_with(R"([{"center": [0,1,0], "reflection": "classic"}])"));
    EXPECT_TRUE(f.environment_capture);
    EXPECT_FALSE(f.distance_channel);  // nobody uses the impostor
    EXPECT_TRUE(f.reference_lut);
    EXPECT_FALSE(f.model_fits);
    f = plan_features(scene_with(
        R"([{"center": [0,1,0], "fresnel": "f82-tint"}, {"center": [1,1,0], "fresnel": "schlick", "reflection": "box-parallax"}])"));
    EXPECT_TRUE(f.distance_channel);
    EXPECT_FALSE(f.reference_lut);
    EXPECT_EQ(f.models, (std::set<std::string>{"f82-tint", "schlick"}));
    EXPECT_EQ(f.shader_variants.size(), 2u);
    f = plan_features(scene_with(R"([{"center": [0,1,0], "reflection": "classic"}])", "{}",
                                 R"({"type": "equirect", "file": "sky.exr"})"));
    EXPECT_FALSE(f.environment_capture);
    EXPECT_TRUE(f.equirect_image);
}

TEST(PreviewPlan, PassesNobodyReadsAreCulled) {
    // Only the CPU reference image: no GPU pass at all.
    Plan plan = build_plan(scene_with(R"([{"center": [0,1,0]}])",
                                      R"({"beauty": false, "difference": false, "metrics": false, "png": false})"));
    EXPECT_TRUE(plan.runs("cpu-reference"));
    EXPECT_FALSE(plan.runs("beauty"));
    EXPECT_FALSE(plan.runs("capture-environment"));
    EXPECT_FALSE(plan.runs("timing"));
    EXPECT_EQ(plan.outputs, (std::vector<std::string>{"reference.exr"}));
    // Only the beauty image: no CPU reference, no timing.
    plan = build_plan(
        scene_with(R"([{"center": [0,1,0]}])", R"({"reference": false, "difference": false, "metrics": false})"));
    EXPECT_TRUE(plan.runs("beauty"));
    EXPECT_TRUE(plan.runs("capture-environment"));
    EXPECT_FALSE(plan.runs("cpu-reference"));
    EXPECT_FALSE(plan.runs("timing"));
    EXPECT_FALSE(plan.runs("localization"));
    // The localization diagnostics alone: one GPU frame and its file, no CPU reference.
    plan = build_plan(scene_with(
        R"([{"center": [0,1,0]}])",
        R"({"beauty": false, "reference": false, "difference": false, "metrics": false, "localization": true})"));
    EXPECT_TRUE(plan.runs("localization"));
    EXPECT_FALSE(plan.runs("beauty"));
    EXPECT_FALSE(plan.runs("cpu-reference"));
    EXPECT_EQ(plan.outputs, (std::vector<std::string>{"localization.exr"}));
    // Metrics need the reference, the beauty and the frame times, even when no image is written.
    plan = build_plan(
        scene_with(R"([{"center": [0,1,0]}])", R"({"beauty": false, "reference": false, "difference": false})"));
    for (const char* pass : {"beauty", "cpu-reference", "timing", "metrics", "capture-environment", "localization"})
        EXPECT_TRUE(plan.runs(pass)) << pass;
    EXPECT_FALSE(plan.runs("difference"));
    const std::string text = explain(plan, scene_with(R"([{"center": [0,1,0]}])"));
    EXPECT_TRUE(test::Contains(text, "difference: culled"));
}

TEST(PreviewPlan, PassOrderRespectsDependencies) {
    const Plan plan = build_plan(scene_with(R"([{"center": [0,1,0], "fresnel": "schlick"}])"));
    std::map<std::string, std::size_t> written_at;
    for (std::size_t i = 0; i < plan.passes.size(); ++i)
        for (const auto& w : plan.passes[i].writes) written_at[w] = i;
    for (std::size_t i = 0; i < plan.passes.size(); ++i)
        for (const auto& r : plan.passes[i].reads)
            if (written_at.count(r)) {
                EXPECT_LT(written_at[r], i) << plan.passes[i].name << " reads " << r;
            }
}

// Issue 17 item 1: roughness and the glossy method per sphere.
TEST(PreviewScene, RoughnessAndGlossyMethodAreParsedStrictly) {
    const Scene mirror = parse_scene(kMinimal, "s.json");
    EXPECT_EQ(mirror.spheres[0].roughness, 0.0);
    EXPECT_FALSE(mirror.spheres[0].rough());
    EXPECT_EQ(mirror.spheres[0].glossy, GlossyMethod::prefiltered);  // the documented default
    EXPECT_EQ(mirror.outputs.reference_samples, 256);
    const Scene rough = parse_scene(R"({"spheres": [{"center": [0, 1, 0], "roughness": 0.25, "glossy": "prefiltered"}],
                                        "outputs": {"reference_samples": 32}})",
                                    "s.json");
    EXPECT_DOUBLE_EQ(rough.spheres[0].roughness, 0.25);
    EXPECT_TRUE(rough.spheres[0].rough());
    EXPECT_EQ(rough.outputs.reference_samples, 32);
    EXPECT_TRUE(rough.warnings.empty());
    EXPECT_TRUE(test::Contains(parse_error(R"({"spheres": [{"center": [0, 1, 0], "roughness": -0.1}]})"),
                               "bad.json: spheres[0].roughness: must be in [0, 1]"));
    EXPECT_TRUE(test::Contains(parse_error(R"({"spheres": [{"center": [0, 1, 0], "roughness": 1.5}]})"),
                               "spheres[0].roughness: must be in [0, 1]"));
    EXPECT_TRUE(test::Contains(
        parse_error(R"({"spheres": [{"center": [0, 1, 0]}, {"center": [0, 1, 0], "roughness": "matte"}]})"),
        "spheres[1].roughness: expected a number"));
    EXPECT_TRUE(
        test::Contains(parse_error(R"({"spheres": [{"center": [0, 1, 0], "roughness": 0.2, "glossy": "blurry"}]})"),
                       "spheres[0].glossy: unknown value 'blurry' (known: auto, prefiltered, localized)"));
    EXPECT_TRUE(test::Contains(parse_error(R"({"spheres": [{"center": [0, 1, 0], "roughness": 0.2, "glossy": 3}]})"),
                               "spheres[0].glossy: expected a string"));
    EXPECT_TRUE(
        test::Contains(parse_error(R"({"spheres": [{"center": [0, 1, 0]}], "outputs": {"reference_samples": 0}})"),
                       "outputs.reference_samples: must be in [1, 65536]"));
    EXPECT_TRUE(test::Contains(parse_error(R"({"environment": {"type": "equirect", "file": "sky.exr"},
                                              "spheres": [{"center": [0, 1, 0], "reflection": "classic", "roughness": 0.3}]})"),
                               "spheres[0].roughness: rough spheres need a captured environment"));
    EXPECT_TRUE(test::Contains(
        parse_error(
            R"({"spheres": [{"center": [0, 1, 0], "roughness": 0.2, "glossy": "localized", "localized_size": 1}]})"),
        "spheres[0].localized_size: must be in [2, 16]"));
    EXPECT_TRUE(test::Contains(
        parse_error(
            R"({"spheres": [{"center": [0, 1, 0], "roughness": 0.2, "glossy": "localized", "localized_size": 32}]})"),
        "spheres[0].localized_size: must be in [2, 16]"));
    const Scene thesis = parse_scene(
        R"({"spheres": [{"center": [0, 1, 0], "roughness": 0.5, "glossy": "localized", "localized_size": 4}]})",
        "s.json");
    EXPECT_EQ(thesis.spheres[0].glossy, GlossyMethod::localized);
    EXPECT_EQ(thesis.spheres[0].localized_size, 4);
    // A method on a mirror means nothing: a warning naming the field.
    const Scene warned = parse_scene(R"({"spheres": [{"center": [0, 1, 0], "glossy": "prefiltered"}]})", "s.json");
    ASSERT_EQ(warned.warnings.size(), 1u);
    EXPECT_TRUE(test::Contains(warned.warnings[0], "spheres[0].glossy: ignored"));
}

// Issue 17 item 4: the planner adds the glossy passes only where a sphere is rough.
TEST(PreviewPlan, AMirrorOnlyScenePlansNoGlossyPass) {
    const Plan plan =
        build_plan(scene_with(R"([{"center": [0,1,0]}, {"center": [1,1,0], "fresnel": "schlick", "roughness": 0}])"));
    for (const Pass& p : plan.passes) {
        EXPECT_NE(p.name, "prefilter-environment");
        EXPECT_NE(p.name, "monte-carlo-reference");
        EXPECT_NE(p.name.rfind("dfg-table", 0), 0u) << p.name;
        EXPECT_NE(p.name.rfind("downsample-environment", 0), 0u) << p.name;
    }
    EXPECT_TRUE(plan.features.downsample_sizes.empty());
    EXPECT_FALSE(plan.features.prefiltered_map);
    EXPECT_FALSE(plan.features.monte_carlo_reference);
    EXPECT_TRUE(plan.features.dfg_models.empty());
    const std::string text = explain(plan, scene_with(R"([{"center": [0,1,0]}])"));
    EXPECT_TRUE(test::Contains(text, "prefilter-environment: no sphere is rough"));
    EXPECT_TRUE(test::Contains(text, "monte-carlo-reference: every sphere is a mirror"));
    EXPECT_EQ(std::count(plan.outputs.begin(), plan.outputs.end(), "reference-stderr.exr"), 0);
    // The mirror sphere shader variants are today's (no glossy #define).
    for (const std::string& v : plan.features.shader_variants) EXPECT_FALSE(test::Contains(v, "GLOSSY")) << v;
}

TEST(PreviewPlan, OneRoughReferenceSpherePlansOneDfgTableNotSix) {
    const Plan plan = build_plan(scene_with(R"([{"center": [0,1,0], "roughness": 0.4},
        {"center": [1,1,0], "fresnel": "schlick"}, {"center": [1,1,0], "fresnel": "f82-tint"},
        {"center": [1,1,0], "fresnel": "lazanyi"}, {"center": [1,1,0], "fresnel": "gulbrandsen"},
        {"center": [-1,1,0], "material": "Cu"}])"));
    std::vector<std::string> dfg;
    for (const Pass& p : plan.passes)
        if (p.name.rfind("dfg-table", 0) == 0) dfg.push_back(p.name);
    EXPECT_EQ(dfg, (std::vector<std::string>{"dfg-table reference"}));
    EXPECT_EQ(plan.features.dfg_models, (std::set<std::string>{"reference"}));
    EXPECT_TRUE(plan.runs("prefilter-environment"));
    EXPECT_TRUE(plan.runs("monte-carlo-reference"));
    EXPECT_EQ(std::count(plan.outputs.begin(), plan.outputs.end(), "reference-stderr.exr"), 1);
    const std::string text = explain(plan, scene_with(R"([{"center": [0,1,0]}])"));
    EXPECT_TRUE(test::Contains(text, "prefilter-environment [GPU]: sphere(s) 0 rough with glossy 'prefiltered'"));
    EXPECT_TRUE(test::Contains(text, "dfg-table reference [CPU]: rough sphere(s) 0 use reference"));
    EXPECT_TRUE(test::Contains(text, "monte-carlo-reference [CPU]: sphere(s) 0 rough"));
    // The beauty frame reads the prefiltered cube and the table; the difference reads the Monte-Carlo reference.
    for (const Pass& p : plan.passes) {
        if (p.name == "beauty") {
            EXPECT_NE(std::find(p.reads.begin(), p.reads.end(), "prefiltered-cube"), p.reads.end());
            EXPECT_NE(std::find(p.reads.begin(), p.reads.end(), "dfg-tables reference"), p.reads.end());
        }
        if (p.name == "difference") {
            EXPECT_NE(std::find(p.reads.begin(), p.reads.end(), "monte-carlo-reference-image"), p.reads.end());
        }
    }
    // Two rough models: one table pass each; no reference asked for: no Monte Carlo.
    const Plan two = build_plan(scene_with(R"([{"center": [0,1,0], "fresnel": "schlick", "roughness": 0.2},
        {"center": [1,1,0], "fresnel": "f82-tint", "roughness": 0.5}, {"center": [1,1,0], "fresnel": "schlick", "material": "Cu", "roughness": 0.5}])",
                                           R"({"reference": false, "difference": false, "metrics": false})"));
    EXPECT_TRUE(two.runs("dfg-table schlick"));
    EXPECT_TRUE(two.runs("dfg-table f82-tint"));
    EXPECT_FALSE(two.runs("dfg-table reference"));
    EXPECT_FALSE(two.runs("monte-carlo-reference"));
    EXPECT_FALSE(two.runs("cpu-reference"));
    EXPECT_FALSE(two.runs("downsample-environment 8"));
    // Localized spheres: one downsample pass per M, no prefilter or table for them; the cube stores distances.
    const Plan thesis =
        build_plan(scene_with(R"([{"center": [0,1,0], "roughness": 0.5, "glossy": "localized", "reflection": "classic"},
        {"center": [1,1,0], "roughness": 0.5, "glossy": "localized", "localized_size": 4, "reflection": "classic"},
        {"center": [1,1,0], "roughness": 0.7, "glossy": "localized", "localized_size": 4, "reflection": "classic"}])"));
    EXPECT_TRUE(thesis.runs("downsample-environment 8"));
    EXPECT_TRUE(thesis.runs("downsample-environment 4"));
    EXPECT_FALSE(thesis.runs("prefilter-environment"));
    EXPECT_TRUE(thesis.features.dfg_models.empty());
    EXPECT_TRUE(thesis.features.distance_channel);
    EXPECT_TRUE(thesis.runs("monte-carlo-reference"));
    const std::string thesis_text = explain(thesis, scene_with(R"([{"center": [0,1,0]}])"));
    EXPECT_TRUE(
        test::Contains(thesis_text, "downsample-environment 4 [GPU]: sphere(s) 1, 2 rough with glossy 'localized'"));
}

// The CPU tracer against geometry worked out by hand.
TEST(PreviewEnvironment, RoomHitsAndRadianceRules) {
    Environment env = scene_with(R"([{"center": [0,1,0]}])", "{}",
                                 R"({"min": [-2, 0, -3], "max": [2, 3, 3], "checker": 1.0,
                                     "panels": [{"min": [-0.5, -0.5], "max": [0.5, 0.5], "radiance": [7, 8, 9]}],
                                     "boxes": [{"min": [1, 0, -0.5], "max": [1.5, 1, 0.5], "color": [0.5, 0.4, 0.3]}]})")
                          .environment;
    const EnvironmentTracer tracer(env);
    const Vec3 o{0, 1, 0};
    EnvironmentHit up = tracer.trace(o, {0, 1, 0});  // the ceiling panel
    EXPECT_DOUBLE_EQ(up.t, 2.0);
    EXPECT_DOUBLE_EQ(up.radiance.g, 8.0);
    EnvironmentHit box = tracer.trace({0, 0.5, 0}, {1, 0, 0});  // the box's −x face, shade 0.7
    EXPECT_DOUBLE_EQ(box.t, 1.0);
    EXPECT_DOUBLE_EQ(box.radiance.r, 0.7 * 0.5);
    EnvironmentHit wall = tracer.trace({0, 0.5, 0.2}, {-1, 0, 0});  // left wall at x = −2, check (z 0.2, y 0.5): even
    EXPECT_DOUBLE_EQ(wall.t, 2.0);
    EXPECT_DOUBLE_EQ(wall.radiance.r, env.room.wall_x_min.r);
    EXPECT_DOUBLE_EQ(tracer.trace({0, 1.5, 0.2}, {-1, 0, 0}).radiance.r, 0.75 * env.room.wall_x_min.r);  // odd check
    const Vec3 d = normalize({0.3, -1, 0.2});  // the floor at y = 0, t = 1/|d.y|
    EnvironmentHit floor = tracer.trace(o, d);
    EXPECT_NEAR(floor.t, 1.0 / std::abs(d.y), 1e-12);
    const Vec3 p = o + floor.t * d;
    const bool even = ((int(std::floor(p.x)) + int(std::floor(p.z))) & 1) == 0;
    EXPECT_DOUBLE_EQ(floor.radiance.r, even ? env.room.floor_light.r : env.room.floor_dark.r);
}

TEST(PreviewEnvironment, SphereRoomDistanceIsTheClosedForm) {
    Environment env;
    env.type = EnvironmentType::sphere_room;
    env.sphere_room.radius = 4;
    env.reference_point = Vec3{0, 1, 0};
    const EnvironmentTracer tracer(env);
    const Vec3 x{0.5, -0.3, 0.8}, r = normalize({1, 2, -0.5});
    const double xr = dot(x, r);
    EXPECT_NEAR(tracer.trace(Vec3{0, 1, 0} + x, r).t, -xr + std::sqrt(xr * xr - dot(x, x) + 16), 1e-12);
    EXPECT_DOUBLE_EQ(tracer.trace({0, 1, 0}, {1, 0, 0}).t, 4.0);
}

TEST(PreviewEnvironment, EquirectSamplesTexelCentresExactlyAndWraps) {
    Image image(8, 4);
    for (int y = 0; y < 4; ++y)
        for (int x = 0; x < 8; ++x) image.set(x, y, {double(x), double(y), 1});
    // Texel (x, y) centre: u = (x + 0.5)/8, v = (y + 0.5)/4; direction from u = 0.5 + atan2(dx, −dz)/2π, v = acos(dy)/π.
    for (int x : {0, 3, 7})
        for (int y : {0, 2}) {
            const double phi = ((x + 0.5) / 8 - 0.5) * 2 * std::numbers::pi, theta = (y + 0.5) / 4 * std::numbers::pi;
            const Vec3 d{std::sin(theta) * std::sin(phi), std::cos(theta), -std::sin(theta) * std::cos(phi)};
            const RGB v = sample_equirect(image, d);
            EXPECT_NEAR(v.r, x, 1e-9);
            EXPECT_NEAR(v.g, y, 1e-9);
        }
    // Half-way across the seam between column 7 and column 0: the mean of the two.
    const double theta = 1.5 / 4 * std::numbers::pi;
    const Vec3 seam{0, std::cos(theta), std::sin(theta)};  // u = 0 (and 1): atan2(0, −z) = ±π
    EXPECT_NEAR(sample_equirect(image, seam).r, 3.5, 1e-9);
}

// Colours are parsed into libfit RGB with the messages the Vec3 reading gave.
TEST(PreviewScene, ColoursAreRgbWithTheSameMessages) {
    EXPECT_EQ(parse_error(R"({"environment": {"ceiling": [0.1, -0.2, 0.3]}, "spheres": [{"center": [0,1,0]}]})"),
              "bad.json: environment.ceiling: radiance must not be negative");
    EXPECT_EQ(parse_error(R"({"environment": {"ceiling": [0.1, 0.2]}, "spheres": [{"center": [0,1,0]}]})"),
              "bad.json: environment.ceiling: expected an array of 3 numbers");
    const Scene scene =
        parse_scene(R"({"environment": {"ceiling": [0.1, 0.2, 0.3]}, "spheres": [{"center": [0,1,0]}]})", "s.json");
    EXPECT_EQ(scene.environment.room.ceiling, (RGB{0.1, 0.2, 0.3}));
}

// A sphere's Fresnel is parsed into a variant (the reference, or a model id with its parameter source); the parse
// rejects what the string fields rejected, with the same messages, and "params" is still checked on a reference sphere.
TEST(PreviewScene, FresnelIsParsedIntoATypedChoice) {
    const std::string bad = "bad.json: spheres[0].";
    EXPECT_EQ(parse_error(R"({"spheres": [{"center": [0, 1, 0], "fresnel": 3}]})"), bad + "fresnel: expected a string");
    EXPECT_EQ(parse_error(R"({"spheres": [{"center": [0, 1, 0], "fresnel": ""}]})"),
              bad + "fresnel: must not be empty");
    EXPECT_EQ(parse_error(R"({"spheres": [{"center": [0, 1, 0], "fresnel": "schlick", "params": "closd"}]})"),
              bad + "params: unknown value 'closd' (known: fit, closed)");
    EXPECT_EQ(parse_error(R"({"spheres": [{"center": [0, 1, 0], "params": "closd"}]})"),
              bad + "params: unknown value 'closd' (known: fit, closed)");
    EXPECT_EQ(parse_error(R"({"spheres": [{"center": [0, 1, 0], "params": true}]})"),
              bad + "params: expected a string");

    const Scene scene = scene_with(R"([{"center": [0,1,0], "fresnel": "f82-tint", "params": "closed"},
                                       {"center": [1,1,0], "fresnel": "schlick"},
                                       {"center": [2,1,0], "fresnel": "reference", "params": "closed"}])");
    const auto* closed = std::get_if<ModelFresnel>(&scene.spheres[0].fresnel);
    ASSERT_NE(closed, nullptr);
    EXPECT_EQ(closed->model, "f82-tint");
    EXPECT_EQ(closed->parameters, ParameterSource::closed);
    EXPECT_EQ(std::get<ModelFresnel>(scene.spheres[1].fresnel).parameters, ParameterSource::fit);
    EXPECT_TRUE(shows_reference(scene.spheres[2]));
    EXPECT_EQ(fresnel_name(scene.spheres[0].fresnel), "f82-tint");
    EXPECT_EQ(fresnel_name(scene.spheres[2].fresnel), "reference");
    // An unknown model id is resolved (and reported) where the sphere's Fresnel data is made, as before: the plan
    // of such a scene can still be explained.
    const Features f = plan_features(scene_with(R"([{"center": [0,1,0], "fresnel": "nope"}])"));
    EXPECT_EQ(f.models, (std::set<std::string>{"nope"}));
}

// The scene's colour space (docs/scene.md, "Colour"): `space` and an equirect's `colorspace` are read; empty or
// mistyped ones are errors naming the field.
TEST(PreviewScene, SpaceAndImageColorspaceAreReadAndChecked) {
    const Scene scene = parse_scene(R"({"space": "ACEScg", "environment": {"type": "equirect", "file": "sky.exr",
                                        "colorspace": "Linear Rec.2020"}, "spheres": [{"center": [0,1,0], "reflection": "classic"}]})",
                                    "scene.json");
    EXPECT_EQ(scene.space, "ACEScg");
    EXPECT_EQ(scene.environment.equirect.colorspace, "Linear Rec.2020");
    EXPECT_TRUE(parse_scene(R"({"spheres": [{"center": [0,1,0]}]})", "scene.json").space.empty());
    EXPECT_TRUE(test::Contains(parse_error(R"({"space": "", "spheres": [{"center": [0,1,0]}]})"),
                               "bad.json: space: must not be empty"));
    EXPECT_TRUE(test::Contains(parse_error(R"({"space": 709, "spheres": [{"center": [0,1,0]}]})"),
                               "bad.json: space: expected a string"));
    EXPECT_TRUE(test::Contains(parse_error(R"({"environment": {"type": "equirect", "file": "sky.exr", "colorspace": ""},
                                              "spheres": [{"center": [0,1,0], "reflection": "classic"}]})"),
                               "bad.json: environment.colorspace: must not be empty"));
    // colorspace belongs to an image: a room has none.
    EXPECT_TRUE(
        test::Contains(parse_error(R"({"environment": {"colorspace": "ACEScg"}, "spheres": [{"center": [0,1,0]}]})"),
                       "environment.colorspace"));
}

// The Fresnel of a scene in ACEScg is the Rec.709 one through the published Rec.709 → ACEScg matrix (Bradford
// D65 → ACES white; e.g. the ACES 1.x sRGB-to-ACEScg matrix), an independent form of OCIO's builtin transform.
TEST(PreviewScene, TheFresnelIsComputedInTheScenesSpace) {
    const OcioConfigChoice config = choose_ocio_config(std::nullopt, test::kData);
    FresnelLibrary rec709(test::kData, config, "", "scene.json"), acescg(test::kData, config, "ACEScg", "scene.json");
    EXPECT_EQ(acescg.converter().space(), "ACEScg");
    Sphere gold;  // reference Fresnel of Au
    const SphereFresnel& a = rec709.get(gold, "spheres[0]");
    const SphereFresnel& b = acescg.get(gold, "spheres[0]");
    constexpr double M[3][3] = {
        {0.6130974, 0.3395231, 0.0473795}, {0.0701937, 0.9163539, 0.0134524}, {0.0206156, 0.1095698, 0.8698147}};
    for (const double mu : {1.0, 0.5, 0.1}) {
        const RGB x = a(mu), y = b(mu);
        for (int c = 0; c < 3; ++c)
            EXPECT_NEAR(y[c], M[c][0] * x.r + M[c][1] * x.g + M[c][2] * x.b, 2e-4) << "mu " << mu << " channel " << c;
    }
    // A space the config lacks is the scene's error, naming `space` and listing what exists.
    try {
        FresnelLibrary bad(test::kData, config, "Linear Rec.710", "scene.json");
        ADD_FAILURE() << "no error";
    } catch (const InputError& e) {
        EXPECT_TRUE(test::Contains(e.what(), "scene.json: space: ")) << e.what();
        EXPECT_TRUE(test::Contains(e.what(), "ACEScg")) << e.what();
    }
}

TEST(PreviewScene, AnUnknownModelIsReportedWhenItsFresnelIsMadeWithTheSameMessage) {
    FresnelLibrary library(test::kData, choose_ocio_config(std::nullopt, test::kData), "", "scene.json");
    Sphere sphere;
    sphere.fresnel = ModelFresnel{"nope", ParameterSource::fit};
    try {
        library.get(sphere, "spheres[1]");
        ADD_FAILURE() << "no error";
    } catch (const InputError& e) {
        EXPECT_TRUE(test::Contains(e.what(), "scene.json: spheres[1].fresnel: unknown model 'nope' (known: "))
            << e.what();
        EXPECT_TRUE(test::Contains(e.what(), ") (or 'reference')")) << e.what();
    }
}

// The GPU benchmarks are one pass graph: asking for one benchmark's record culls every pass of the other, and the
// graph creates each GL resource just before the pass that uses it and frees it after its last use.
std::vector<std::string> pass_names(const graph::PassGraph& g) {
    std::vector<std::string> names;
    for (const auto& p : g.passes()) names.push_back(p.name);
    return names;
}
const graph::Lifetime& lifetime(const graph::PassGraph& g, const std::string& resource) {
    const auto& all = g.lifetimes();
    const auto it =
        std::find_if(all.begin(), all.end(), [&](const graph::Lifetime& l) { return l.resource == resource; });
    if (it == all.end()) throw std::runtime_error("no lifetime of " + resource);
    return *it;
}
bool culled(const graph::PassGraph& g, const std::string& pass) {
    return std::any_of(g.skipped().begin(), g.skipped().end(),
                       [&](const graph::SkippedPass& s) { return s.name == pass && s.why.starts_with("culled"); });
}

TEST(PreviewBenchGraph, TheShaderBenchmarkRunsOnlyItsPasses) {
    GpuBenchRun run{{test::kData, choose_ocio_config(std::nullopt, test::kData), {}, 0},
                    true,
                    nullptr,
                    localization_rooms(test::kData, true),
                    {},
                    {}};
    graph::PassGraph g;
    const GpuBenchHandles records = add_gpu_bench_passes(g, run);
    g.request(records.shaders);
    g.compile();
    EXPECT_EQ(pass_names(g), (std::vector<std::string>{"model-cost-programs", "shader-timing", "shader-record"}));
    for (const char* pass : {"bench-fresnel", "cpu-reference empty", "capture-environment difficult",
                             "localization-timing empty", "localization-record"})
        EXPECT_TRUE(culled(g, pass)) << pass;
    EXPECT_EQ(lifetime(g, "cost-target").first, 1u);  // made for the timing pass, freed after it
    EXPECT_EQ(lifetime(g, "cost-target").last, 1u);
    EXPECT_FALSE(run.library);  // the localization's libfit work never started
}

TEST(PreviewBenchGraph, TheLocalizationBenchmarkFreesEachRoomsCubeBeforeTheNextIsMade) {
    GpuBenchRun run{{test::kData, choose_ocio_config(std::nullopt, test::kData), {}, 0},
                    true,
                    nullptr,
                    localization_rooms(test::kData, true),
                    {},
                    {}};
    ASSERT_EQ(run.rooms.size(), 2u);
    EXPECT_TRUE(run.rooms[0].scene.environment.room.boxes.empty());
    EXPECT_FALSE(run.rooms[1].scene.environment.room.boxes.empty());
    graph::PassGraph g;
    const GpuBenchHandles records = add_gpu_bench_passes(g, run);
    g.request(records.localization);
    g.compile();
    EXPECT_EQ(pass_names(g), (std::vector<std::string>{"bench-fresnel", "cpu-reference empty",
                                                       "capture-environment empty", "localization-timing empty",
                                                       "cpu-reference difficult", "capture-environment difficult",
                                                       "localization-timing difficult", "localization-record"}));
    for (const char* pass : {"model-cost-programs", "shader-timing", "shader-record"})
        EXPECT_TRUE(culled(g, pass)) << pass;
    EXPECT_LT(lifetime(g, "environment-cube empty").last, lifetime(g, "environment-cube difficult").first);
    EXPECT_EQ(lifetime(g, "renderer empty").last, lifetime(g, "environment-cube empty").last);
}

// The PNGs' display transform is libfit's: scene-linear → sRGB display, clamped, 8 bits; a config it cannot use is
// a ColorConfigError naming the config and no command-line flag.
TEST(PreviewDisplay, LibfitsDisplayTransformEncodesSceneLinearAsSrgb) {
    const DisplayTransform display = DisplayTransform::create(choose_ocio_config(std::nullopt, test::kData));
    const std::vector<float> linear{0.0f, 1.0f, 0.18f, 2.0f, -1.0f, 0.5f};
    const std::vector<unsigned char> encoded = display.apply(linear, 2, 1);
    // sRGB's curve: 0.18 → 0.4614 → 118, 0.5 → 0.7354 → 188; 2 and −1 clamp.
    EXPECT_EQ(encoded, (std::vector<unsigned char>{0, 255, 118, 255, 0, 188}));
    EXPECT_NE(display.description().find("sRGB"), std::string::npos) << display.description();
    try {
        DisplayTransform::create({test::kData / "no-such.ocio", "explicit"});
        ADD_FAILURE() << "no error";
    } catch (const ColorConfigError& e) {
        const std::string what = e.what();
        EXPECT_NE(what.find("no-such.ocio: no display transform from scene_linear"), std::string::npos) << what;
        EXPECT_EQ(what.find("--"), std::string::npos) << what;
    }
}

}  // namespace test_preview_scene
}  // namespace metalfit::glpreview
