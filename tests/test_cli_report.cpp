// metalfit report end to end: report.json against the fit record and independent forms, byte-identical reruns,
// no absolute paths, the --fail-above gate, and failures that leave nothing behind. (The pages themselves are
// checked in a real browser: report.browser, tests/report_browser.mjs.)
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <numbers>
#include <set>
#include <sstream>

#include "test_support.hpp"

namespace test_cli_report {

namespace fs = std::filesystem;
using metalfit::test::read_file;
using Json = nlohmann::json;

class Report : public ::testing::Test {
protected:
    metalfit::test::CommandResult run(const std::string& args) const {
        return metalfit::test::run_command(metalfit::test::kMetalfitExe, args, tmp_.path());
    }
    Json report_json(const fs::path& dir) const { return Json::parse(read_file(dir / "report.json")); }
    std::size_t entries() const { return std::distance(fs::directory_iterator(tmp_.path()), fs::directory_iterator()); }
    metalfit::test::TempDir tmp_;
};

std::vector<fs::path> files_below(const fs::path& dir) {
    std::vector<fs::path> files;
    for (const auto& e : fs::recursive_directory_iterator(dir))
        if (e.is_regular_file()) files.push_back(fs::relative(e.path(), dir));
    std::sort(files.begin(), files.end());
    return files;
}

// Every model's closed forms, best closed form and fit (params, all seven metrics per channel, where the maxima
// are, the solver) are those of `metalfit fit --json` with the same options.
void expect_same_numbers_as_the_fit_record(const Json& report, const Json& record) {
    ASSERT_EQ(report["materials"].size(), record["materials"].size());
    for (const Json& m : report["materials"]) {
        const Json& fitted = record["materials"].at(m["id"].get<std::string>());
        ASSERT_EQ(m["models"].size(), fitted["models"].size());
        for (const auto& [id, model] : fitted["models"].items())
            for (const char* key : {"fit", "closed", "closed_forms"}) {
                EXPECT_EQ(m["models"].at(id).at(key), model.at(key)) << m["id"] << " " << id << " " << key;
                if (std::string(key) == "fit") {
                    for (const char* metric : {"rel_rms", "abs_rms", "max_rel", "max_abs", "albedo_err"})
                        EXPECT_EQ(m["models"][id]["fit"]["metrics"][metric].size(), 3u) << metric;
                }
            }
        EXPECT_EQ(m["F0"], fitted["F0"]) << m["id"];
    }
}

TEST_F(Report, NumbersAreTheFitRecordsForTheSameOptions) {
    const fs::path dir = tmp_.path() / "r";
    for (const std::string& options :
         {std::string(""), std::string(" --space ACEScg --weight cosine --metric abs --nodes 64")}) {
        const auto r = run("report Au,Zn --renders off -o '" + dir.string() + "'" + options);
        ASSERT_EQ(r.exit_code, 0) << r.err;
        const Json report = report_json(dir);
        // The report's fits hold the recommendation's F0 error (--max-f0-error, 0.5 %): fit's --f0-tolerance.
        Json record = Json::parse(run("fit Au --json --f0-tolerance 0.5%" + options).out);
        record["materials"].update(Json::parse(run("fit Zn --json --f0-tolerance 0.5%" + options).out)["materials"]);
        expect_same_numbers_as_the_fit_record(report, record);
        EXPECT_EQ(report["schema"], "metalfit.report/1");
        EXPECT_EQ(report["provenance"]["color_space"], record["provenance"]["color_space"]);
        EXPECT_EQ(report["provenance"]["metric"], record["provenance"]["metric"]);
        EXPECT_EQ(report["provenance"]["constraints"], record["provenance"]["constraints"]);
    }
}

// What each consumer renders: the report's per-model `consumers` are the export record's (metalfit_export.json's
// export.consumers) wherever the report's fit is the export's (the report holds F0 errors to 0.5 %, so a channel
// beyond that is fitted differently there and left out here); glTF's is Schlick, and differs from the fit's.
TEST_F(Report, ConsumersAreTheExportRecordsForTheSameFits) {
    const fs::path report_dir = tmp_.path() / "r", export_dir = tmp_.path() / "e";
    ASSERT_EQ(run("report Al,Cu,Ni --renders off -o '" + report_dir.string() + "'").exit_code, 0);
    const auto e =
        run("export Al,Cu,Ni --model all --format json,mtlx,openpbr,gltf,blender -o '" + export_dir.string() + "'");
    ASSERT_EQ(e.exit_code, 0) << e.err;
    const Json report = report_json(report_dir);
    const Json record = Json::parse(read_file(export_dir / "metalfit_export.json"));
    int compared = 0;
    for (const Json& material : report["materials"])
        for (const auto& [model, entry] : material["models"].items()) {
            const Json& exported = record["materials"][material["id"].get<std::string>()]["models"][model];
            if (entry["fit"]["params"] != exported["fit"]["params"]) continue;
            ASSERT_EQ(entry["consumers"].size(), 4u) << model;
            for (const auto& [format, c] : entry["consumers"].items()) {
                const Json& x = exported["export"]["consumers"][format];
                // A stand-in's figures compare only where its fit is the export's too.
                const std::string rendered = c["model"];
                if (rendered != "schlick" &&
                    material["models"][rendered]["fit"]["params"] !=
                        record["materials"][material["id"].get<std::string>()]["models"][rendered]["fit"]["params"])
                    continue;
                EXPECT_EQ(c["curve"], x["curve"]) << model << " " << format;
                EXPECT_EQ(c["model"], x["model"]) << model << " " << format;
                double worst = 0;
                for (const Json& v : x["metrics"]["rel_rms"]) worst = std::max(worst, v.get<double>());
                EXPECT_NEAR(c["worst_rel_rms"].get<double>(), worst, 1e-12 * worst) << model << " " << format;
                EXPECT_NEAR(c["de2000_max"].get<double>(), x["metrics"]["de2000_max"].get<double>(), 1e-9)
                    << model << " " << format;
                ++compared;
            }
            EXPECT_EQ(entry["consumers"]["gltf"]["model"], "schlick");
            if (model != "schlick") {
                EXPECT_NE(entry["consumers"]["gltf"]["worst_rel_rms"], entry["worst_rel_rms"]) << model;
            }
        }
    EXPECT_GE(compared, 40) << "too few fits equal between the report and the export to compare";
}

// The plotted curves against forms computed here: R at θ = 0 is `show`'s F0, Schlick's curve is
// F0 + (1 − F0)(1 − μ)^5 of its fitted F0, μ = cos θ, and the relative rms of every model is its worst channel.
TEST_F(Report, CurvesAgreeWithIndependentForms) {
    const fs::path dir = tmp_.path() / "r";
    ASSERT_EQ(run("report Cu --renders off -o '" + dir.string() + "'").exit_code, 0);
    const Json m = report_json(dir)["materials"][0];
    const Json show = Json::parse(run("show Cu --json").out);
    const Json& c = m["curves"];
    ASSERT_EQ(c["theta_deg"].size(), 91u);
    for (int ch = 0; ch < 3; ++ch) {
        EXPECT_NEAR(c["exact"][ch][0].get<double>(), show["F0"][ch].get<double>(), 1e-5);
        EXPECT_NEAR(c["exact"][ch][90].get<double>(), 1.0, 1e-5);  // grazing: every metal reflects everything
    }
    const Json& schlick = m["models"]["schlick"];
    for (std::size_t i = 0; i < c["theta_deg"].size(); ++i) {
        const double theta = c["theta_deg"][i].get<double>();
        const double mu = std::cos(theta * std::numbers::pi / 180);
        EXPECT_NEAR(c["mu"][i].get<double>(), mu, 1e-6);
        for (int ch = 0; ch < 3; ++ch) {
            const double f0 = schlick["fit"]["params"]["F0"][ch].get<double>();
            EXPECT_NEAR(schlick["curve"][ch][i].get<double>(), f0 + (1 - f0) * std::pow(1 - mu, 5), 2e-6) << theta;
        }
        EXPECT_GE(schlick["de2000"][i].get<double>(), 0.0);
        EXPECT_EQ(schlick["stripe"][i].get<std::string>().size(), 7u);
    }
    for (const auto& [id, model] : m["models"].items()) {
        double worst = 0;
        for (const auto& v : model["fit"]["metrics"]["rel_rms"]) worst = std::max(worst, v.get<double>());
        EXPECT_EQ(model["worst_rel_rms"].get<double>(), worst) << id;
    }
    // Copper has alternate measurements: each source's F0 and their spread.
    ASSERT_FALSE(m["data_sources"].is_null());
    const Json& sources = m["data_sources"]["sources"];
    ASSERT_GE(sources.size(), 2u);
    for (int ch = 0; ch < 3; ++ch) {
        double lo = 1e9, hi = -1e9;
        for (const Json& s : sources)
            if (s.contains("F0"))
                lo = std::min(lo, s["F0"][ch].get<double>()), hi = std::max(hi, s["F0"][ch].get<double>());
        EXPECT_DOUBLE_EQ(m["data_sources"]["spread"]["F0"][ch].get<double>(), hi - lo);
    }
    EXPECT_EQ(sources[0]["F0"], show["F0"]);
}

// The viewer's inputs: the LUT (R_c at μ = i/255) ends at show's F0 and at 1 (grazing) and, interpolated linearly in
// μ, matches the curve sampled in θ; each model's GLSL is the text the GLSL export writes for it.
TEST_F(Report, ViewerLutAndShadersAreTheReferenceAndTheGlslExport) {
    const fs::path dir = tmp_.path() / "r";
    ASSERT_EQ(run("report Cu --model schlick,f82-tint,rational --renders off -o '" + dir.string() + "'").exit_code, 0);
    const Json report = report_json(dir);
    const Json& m = report["materials"][0];
    const Json show = Json::parse(run("show Cu --json").out);
    ASSERT_EQ(m["lut"].size(), 3u);
    for (int ch = 0; ch < 3; ++ch) {
        const Json& row = m["lut"][ch];
        ASSERT_EQ(row.size(), 256u);
        EXPECT_NEAR(row[255].get<double>(), show["F0"][ch].get<double>(), 1e-5);
        EXPECT_NEAR(row[0].get<double>(), 1.0, 1e-5);
        for (int theta = 0; theta <= 80; ++theta) {
            const double x = std::cos(theta * std::numbers::pi / 180) * 255;
            const int i = std::min(static_cast<int>(x), 254);
            const double lerp = row[i].get<double>() + (x - i) * (row[i + 1].get<double>() - row[i].get<double>());
            EXPECT_NEAR(lerp, m["curves"]["exact"][ch][theta].get<double>(), 1e-4) << theta;
        }
    }
    ASSERT_EQ(report["models"].size(), 3u);
    for (const Json& model : report["models"]) {
        const std::string id = model["id"], function = model["glsl"]["function"], source = model["glsl"]["source"];
        EXPECT_NE(source.find("vec3 " + function + "("), std::string::npos) << id;
        const fs::path out = tmp_.path() / ("glsl-" + id);
        ASSERT_EQ(run("export Cu --model " + id + " --format glsl -o '" + out.string() + "'").exit_code, 0) << id;
        EXPECT_NE(read_file(out / "glsl" / "metalfit_models.glsl").find(source), std::string::npos) << id;
    }
}

// --sources primary: the material's fit without the other measurements of the catalog; the fits are the same.
TEST_F(Report, SourcesPrimaryLeavesOutTheOtherMeasurements) {
    const fs::path all = tmp_.path() / "all", primary = tmp_.path() / "primary";
    ASSERT_EQ(run("report Cu --model schlick --renders off -o '" + all.string() + "'").exit_code, 0);
    const auto r = run("report Cu --model schlick --renders off --sources primary -o '" + primary.string() + "'");
    ASSERT_EQ(r.exit_code, 0) << r.err;
    const Json a = report_json(all)["materials"][0], p = report_json(primary)["materials"][0];
    EXPECT_FALSE(a["data_sources"].is_null());
    EXPECT_TRUE(p["data_sources"].is_null());
    EXPECT_EQ(a["models"], p["models"]);
    EXPECT_EQ(run("report Cu --renders off --sources some -o '" + (tmp_.path() / "x").string() + "'").exit_code, 2);
}

// A user file is reported with its own provenance, even when its name is a catalog id: no catalog licence, DOI or
// alternate sources are borrowed for it.
TEST_F(Report, AUserFileNamedLikeACatalogMaterialIsNotTheCatalogs) {
    const fs::path file = tmp_.path() / "Au.yml";
    fs::copy_file(metalfit::test::kFixtures / "valid-unsorted-duplicates.yml", file);
    const fs::path dir = tmp_.path() / "r";
    const auto r = run("report '" + file.string() + "' --renders off -o '" + dir.string() + "'");
    ASSERT_EQ(r.exit_code, 0) << r.err;
    const Json m = report_json(dir)["materials"][0];
    EXPECT_EQ(m["id"], "Au");
    EXPECT_EQ(m["provenance"]["file"], "outside:Au.yml");  // outside the database and the working folder
    EXPECT_TRUE(m["provenance"]["licence"].is_null());
    EXPECT_TRUE(m["provenance"]["kind"].is_null());
    EXPECT_TRUE(m["data_sources"].is_null());
    EXPECT_TRUE(fs::exists(dir / "materials" / "Au.html"));
}

TEST_F(Report, RerunsAreByteIdenticalAndNameNoPathOfThisMachine) {
    const fs::path a = tmp_.path() / "a", b = tmp_.path() / "b";
    ASSERT_EQ(run("report Au,Cu --renders off -o '" + a.string() + "'").exit_code, 0);
    ASSERT_EQ(run("report Au,Cu --renders off -o '" + b.string() + "'").exit_code, 0);
    const auto files = files_below(a);
    ASSERT_EQ(files, files_below(b));
    for (const char* expected :
         {"index.html", "materials/Au.html", "materials/Cu.html", "report.json", "assets/report-data.js",
          "assets/vega.min.js", "assets/vega-lite.min.js", "assets/vega-embed.min.js", "assets/report.js"})
        EXPECT_TRUE(std::find(files.begin(), files.end(), fs::path(expected)) != files.end()) << expected;
    for (const fs::path& f : files) EXPECT_EQ(read_file(a / f), read_file(b / f)) << f;
    const std::string json = read_file(a / "report.json");
    EXPECT_EQ(json.find(metalfit::test::kData.string()), std::string::npos);
    EXPECT_EQ(json.find(tmp_.path().string()), std::string::npos);
    EXPECT_EQ(read_file(a / "assets/report-data.js"), "metalfitReport(" + json + ");\n");
    EXPECT_EQ(report_json(a)["renders"]["skipped"], "--renders off");
}

TEST_F(Report, FailAboveListsEveryChannelAboveTheLimitAndExitsWith6) {
    const fs::path dir = tmp_.path() / "r";
    const auto r = run("report Zn,Au --renders off --fail-above 1% -o '" + dir.string() + "'");
    EXPECT_EQ(r.exit_code, 6) << r.err;
    // The lines, counted independently from the fit record.
    std::set<std::string> expected;
    for (const char* material : {"Zn", "Au"}) {
        const Json record = Json::parse(run(std::string("fit ") + material + " --json").out);
        for (const auto& [model, result] : record["materials"][material]["models"].items())
            for (int c = 0; c < 3; ++c)
                if (result["fit"]["metrics"]["rel_rms"][c].get<double>() > 0.01)
                    expected.insert(std::string(material) + ": " + model + ": " +
                                    std::array{"red", "green", "blue"}[c]);
    }
    ASSERT_FALSE(expected.empty());
    std::set<std::string> listed;
    std::istringstream lines(r.err);
    for (std::string line; std::getline(lines, line);) {
        const std::string prefix = "metalfit: above --fail-above: ";
        if (line.rfind(prefix, 0) != 0) continue;
        EXPECT_TRUE(metalfit::test::Contains(line, "> 1 %"));
        listed.insert(line.substr(prefix.size(), line.find(": fitted") - prefix.size()));
    }
    EXPECT_EQ(listed, expected);
    EXPECT_TRUE(fs::exists(dir / "index.html")) << "the report is written before the gate fails";

    const auto passing = run("report Zn --model gulbrandsen --renders off --fail-above 0.5% -o '" + dir.string() + "'");
    EXPECT_EQ(passing.exit_code, 0) << passing.err;
    EXPECT_EQ(run("report Zn --renders off --fail-above 5 -o '" + dir.string() + "'").exit_code, 0)
        << "a fraction, not %";
    const auto bad = run("report Zn --fail-above lots -o '" + dir.string() + "'");
    EXPECT_EQ(bad.exit_code, 2);
    EXPECT_TRUE(metalfit::test::Contains(bad.err, "--fail-above"));
}

TEST_F(Report, FailuresAreOneLineWithTheirExitCodeAndLeaveNothing) {
    const auto expect_one_line = [](const metalfit::test::CommandResult& r, int code, const std::string& text) {
        EXPECT_EQ(r.exit_code, code) << r.err;
        EXPECT_EQ(std::count(r.err.begin(), r.err.end(), '\n'), 1) << r.err;
        EXPECT_TRUE(metalfit::test::Contains(r.err, text));
    };
    const fs::path dir = tmp_.path() / "r";
    expect_one_line(run("report unobtainium -o '" + dir.string() + "'"), 2, "unknown material 'unobtainium'");
    expect_one_line(run("report Au,unobtainium --renders off -o '" + dir.string() + "'"), 2, "unobtainium");
    expect_one_line(run("report Au,gold --renders off -o '" + dir.string() + "'"), 2, "named twice");
    expect_one_line(run("report Au --renders sometimes -o '" + dir.string() + "'"), 2, "--renders");
    EXPECT_EQ(entries(), 0u);
    // Unwritable: under a missing folder, under a file, a file in its place, where no folder can be made (/proc).
    std::ofstream(tmp_.path() / "file") << "x";
    expect_one_line(run("report Au --renders off -o '" + (tmp_.path() / "missing" / "r").string() + "'"), 3, "missing");
    expect_one_line(run("report Au --renders off -o '" + (tmp_.path() / "file" / "r").string() + "'"), 3, "file");
    expect_one_line(run("report Au --renders off -o '" + (tmp_.path() / "file").string() + "'"), 3, "not a folder");
    expect_one_line(run("report Au --renders off -o /proc/metalfit-report"), 3, "/proc/metalfit-report");
    EXPECT_EQ(entries(), 1u) << "only the file made above";
    EXPECT_EQ(read_file(tmp_.path() / "file"), "x");
}

// The PNG's size from its IHDR chunk (bytes 16–23, big-endian).
std::pair<int, int> png_size(const std::string& png) {
    auto be32 = [&](std::size_t at) {
        return (int(static_cast<unsigned char>(png[at])) << 24) | (int(static_cast<unsigned char>(png[at + 1])) << 16) |
               (int(static_cast<unsigned char>(png[at + 2])) << 8) | int(static_cast<unsigned char>(png[at + 3]));
    };
    return {be32(16), be32(20)};
}

// Issue 16: the renders per model, reference | model | signed error view, from glpreview's sheet with the report's
// models (one column group each).
TEST_F(Report, RendersOneColumnGroupPerModelOfTheReport) {
    const fs::path glpreview = fs::path(metalfit::test::kMetalfitExe).parent_path() / "glpreview";
    if (!fs::exists(glpreview)) GTEST_SKIP() << "glpreview not built";
    const fs::path dir = tmp_.path() / "r";
    const auto r = run("report Au,Zn --model f82-tint,schlick,conductor-rgb --renders on -o '" + dir.string() + "'");
    ASSERT_EQ(r.exit_code, 0) << r.err;
    const Json report = report_json(dir);
    const Json& renders = report["renders"];
    ASSERT_FALSE(renders.contains("skipped")) << renders;
    EXPECT_EQ(renders["models"], Json({"f82-tint", "schlick", "conductor-rgb"}));
    ASSERT_EQ(renders["rows"].size(), 2u);
    // Issue 32: one image per material (glpreview --sheet-rows), named as its page, one row of cells; no sheet.
    EXPECT_FALSE(fs::exists(dir / "assets" / "renders" / "sheet.png"));
    const int cell = renders["cell"][0].get<int>();
    std::set<std::string> images;
    for (std::size_t row = 0; row < 2; ++row) {
        const std::string material = renders["rows"][row]["material"].get<std::string>();
        EXPECT_EQ(renders["rows"][row]["image"], "assets/renders/" + material + ".png");
        const std::string png = read_file(dir / renders["rows"][row]["image"].get<std::string>());
        images.insert(png);
        const auto [width, height] = png_size(png);
        EXPECT_EQ(width, (1 + 2 * 3) * cell) << material;
        EXPECT_EQ(height, cell) << material;
        const Json& models = renders["rows"][row]["models"];
        ASSERT_EQ(models.size(), 3u);
        std::set<int> columns;
        for (std::size_t m = 0; m < 3; ++m) {
            EXPECT_EQ(models[m]["model"], renders["models"][m]);
            ASSERT_EQ(models[m]["cells"].size(), 1u) << "the mirror only";
            const Json& c = models[m]["cells"][0];
            EXPECT_EQ(c["roughness"], 0.0);
            EXPECT_EQ(c["reference"], 0);
            columns.insert(c["model"].get<int>());
            columns.insert(c["difference"].get<int>());
            EXPECT_GT(c["image_rmse"].get<double>(), 0.0);
            // The error view's scale (the images carry no labels: the page prints it), the row's: one per material.
            EXPECT_GE(c["error_view"][0].get<double>(), 1e-5);
            EXPECT_GT(c["error_view"][1].get<double>(), c["error_view"][0].get<double>());
            EXPECT_EQ(c["error_view"], models[0]["cells"][0]["error_view"]);
        }
        EXPECT_EQ(columns.size(), 6u) << "each model's cells have columns of their own";
    }
    EXPECT_EQ(images.size(), 2u) << "gold's and zinc's renders differ";
    EXPECT_EQ(files_below(dir / "assets" / "renders").size(), 2u) << "nothing but the materials' images";
    // Each material page finds its row.
    for (const Json& m : report["materials"])
        EXPECT_EQ(renders["rows"][m["render_row"].get<int>()]["material"], m["id"]);
    // A rerun with renders is byte-identical too (the labelled PNG included).
    const fs::path again = tmp_.path() / "again";
    ASSERT_EQ(
        run("report Au,Zn --model f82-tint,schlick,conductor-rgb --renders on -o '" + again.string() + "'").exit_code,
        0);
    ASSERT_EQ(files_below(dir), files_below(again));
    for (const fs::path& f : files_below(dir)) EXPECT_EQ(read_file(dir / f), read_file(again / f)) << f;
}

// Issue 29 item 6: the user's own file and a named finish get renders like catalog materials, and --film/--coat
// reach them: each row is the material the report fitted (a filmed titanium's reference differs from the bare one's).
TEST_F(Report, UserFilesFinishesAndLayersAreRendered) {
    const fs::path file = tmp_.path() / "mygold.yml";
    fs::copy_file(metalfit::test::kData / "nk" / "Au" / "Johnson.yml", file);
    const fs::path dir = tmp_.path() / "r";
    auto r =
        run("report '" + file.string() + "' anodized-ti-80nm --model schlick --renders on -o '" + dir.string() + "'");
    ASSERT_EQ(r.exit_code, 0) << r.err;
    Json report = report_json(dir);
    ASSERT_FALSE(report["renders"].contains("skipped")) << report["renders"];
    ASSERT_EQ(report["renders"]["rows"].size(), 2u);
    for (const Json& m : report["materials"]) {
        ASSERT_TRUE(m["render_row"].is_number()) << m["id"];
        EXPECT_EQ(report["renders"]["rows"][m["render_row"].get<int>()]["material"], m["id"]);
    }
    for (const Json& row : report["renders"]["rows"])
        EXPECT_FALSE(read_file(dir / row["image"].get<std::string>()).empty()) << row["material"];
    const fs::path bare = tmp_.path() / "bare", filmed = tmp_.path() / "filmed";
    ASSERT_EQ(run("report Ti --model schlick --renders on -o '" + bare.string() + "'").exit_code, 0);
    r = run("report Ti --film TiO2:50nm --model schlick --renders on -o '" + filmed.string() + "'");
    ASSERT_EQ(r.exit_code, 0) << r.err;
    const Json filmed_rows = report_json(filmed)["renders"]["rows"];
    ASSERT_EQ(filmed_rows.size(), 1u);
    EXPECT_NE(read_file(bare / report_json(bare)["renders"]["rows"][0]["image"].get<std::string>()),
              read_file(filmed / filmed_rows[0]["image"].get<std::string>()));
}

// Issue 29 item 6: on a terminal the report shows its fits' and renders' progress per material on stderr (the line
// cleared at the end); piped, stderr stays empty. util-linux's script(1) gives the run a terminal.
TEST_F(Report, ProgressShowsOnATerminalAndNotWhenPiped) {
    if (!fs::exists("/usr/bin/script")) GTEST_SKIP() << "util-linux script(1) is not installed";
    const fs::path terminal = tmp_.path() / "terminal", piped = tmp_.path() / "piped";
    const std::string report =
        "'" + std::string(metalfit::test::kMetalfitExe) + "' report Au,Cu --model schlick --renders on -o ";
    const auto tty = metalfit::test::run_command(
        "/usr/bin/script", "-qfec \"" + report + "'" + terminal.string() + "'\" /dev/null", tmp_.path());
    ASSERT_EQ(tty.exit_code, 0) << tty.out << tty.err;
    EXPECT_TRUE(metalfit::test::Contains(tty.out, "metalfit report: fits: 2/2 materials")) << tty.out;
    EXPECT_TRUE(metalfit::test::Contains(tty.out, "metalfit report: renders: 1/2 materials")) << tty.out;
    EXPECT_TRUE(metalfit::test::Contains(tty.out, "metalfit report: renders: 2/2 materials")) << tty.out;
    const auto quiet = run("report Au,Cu --model schlick --renders on -o '" + piped.string() + "'");
    ASSERT_EQ(quiet.exit_code, 0) << quiet.err;
    EXPECT_EQ(quiet.err, "");
    EXPECT_EQ(read_file(terminal / "report.json"), read_file(piped / "report.json"));
}

// Without glpreview beside metalfit, --renders auto still writes the report and says why there are no renders.
TEST_F(Report, WithoutGlpreviewTheRendersAreSkippedWithTheReason) {
    const fs::path bin = tmp_.path() / "bin";
    fs::create_directories(bin);
    fs::copy_file(metalfit::test::kMetalfitExe, bin / "metalfit");
    const fs::path dir = tmp_.path() / "r";
    const auto r = metalfit::test::run_command(bin / "metalfit", "report Au --model schlick -o '" + dir.string() + "'",
                                               tmp_.path());
    ASSERT_EQ(r.exit_code, 0) << r.err;
    EXPECT_EQ(report_json(dir)["renders"]["skipped"], "glpreview was not built beside metalfit");
    EXPECT_FALSE(fs::exists(dir / "assets" / "renders"));
    const auto on = metalfit::test::run_command(
        bin / "metalfit", "report Au --model schlick --renders on -o '" + (tmp_.path() / "on").string() + "'",
        tmp_.path());
    EXPECT_EQ(on.exit_code, 3) << on.err;
    EXPECT_FALSE(fs::exists(tmp_.path() / "on"));
}

}  // namespace test_cli_report
