// End-to-end tests of the metalfit executable: outputs, exit codes, one-line errors, no partial files.
#include <gtest/gtest.h>

#include "test_support.hpp"
#include <nlohmann/json.hpp>

#include <filesystem>
#include <fstream>
#include <algorithm>
#include <cstdio>
#include <sstream>

namespace {

using metalfit::test::read_file;

namespace fs = std::filesystem;

using Result = metalfit::test::CommandResult;


class Cli : public ::testing::Test {
protected:
    void SetUp() override {
        dir_ = fs::temp_directory_path() /
               ("metalfit-cli-" + std::string(::testing::UnitTest::GetInstance()->current_test_info()->name()));
        fs::remove_all(dir_);
        fs::create_directories(dir_);
    }
    void TearDown() override { fs::remove_all(dir_); }

    // Runs metalfit with `args` (already shell-quoted) and an optional environment prefix.
    Result run(const std::string& args, const std::string& env = "OCIO=") const {
        return metalfit::test::run_command(METALFIT_EXE, args, dir_, env);
    }

    static void expect_one_line_error(const Result& r, const std::string& must_contain) {
        EXPECT_FALSE(r.err.empty());
        EXPECT_EQ(std::count(r.err.begin(), r.err.end(), '\n'), 1) << r.err;
        EXPECT_NE(r.err.find(must_contain), std::string::npos) << r.err;
        EXPECT_TRUE(r.out.empty()) << r.out;
    }

    fs::path dir_;
};

const std::string kFixtures = metalfit::test::kFixtures.string();

TEST_F(Cli, ShowJsonHasTheDocumentedKeys) {
    const Result r = run("show gold --json");
    ASSERT_EQ(r.exit_code, 0) << r.err;
    const auto j = nlohmann::json::parse(r.out);
    EXPECT_EQ(j["material"], "Au");
    EXPECT_EQ(j["space"], "Linear Rec.709 (sRGB)");
    ASSERT_EQ(j["F0"].size(), 3u);
    ASSERT_EQ(j["F82"].size(), 3u);
    EXPECT_GT(j["F0"][0].get<double>(), 1.0);  // kept out of gamut
    EXPECT_EQ(j["out_of_gamut"][0]["quantity"], "F0");
    EXPECT_EQ(j["provenance"]["sha256"].get<std::string>().size(), 64u);
    EXPECT_EQ(j["provenance"]["cmf"], "CIE 1931 2°");
}

TEST_F(Cli, ShowOptionsChangeTheResult) {
    const auto base = nlohmann::json::parse(run("show Cu --json").out);
    for (const char* option : {"--cmf 1964", "--illuminant A", "--interp pchip", "--space ACEScg", "--source McPeak"}) {
        const Result r = run(std::string("show Cu --json ") + option);
        ASSERT_EQ(r.exit_code, 0) << option << ": " << r.err;
        const auto j = nlohmann::json::parse(r.out);
        EXPECT_NE(j["F0"], base["F0"]) << option;
    }
}

TEST_F(Cli, UserFilesWorkLikeCatalogNames) {
    const Result yaml = run("show '" + kFixtures + "/valid-unsorted-duplicates.yml' --json");
    ASSERT_EQ(yaml.exit_code, 0) << yaml.err;
    const Result csv = run("show '" + kFixtures + "/valid-nk.csv' --json");
    ASSERT_EQ(csv.exit_code, 0) << csv.err;
    // Both hold Johnson & Christy's gold rows from 300 to 892 nm: the same colour as the catalog's gold.
    const auto gold = nlohmann::json::parse(run("show Au --json").out);
    for (const auto& r : {yaml, csv}) {
        const auto j = nlohmann::json::parse(r.out);
        for (int c = 0; c < 3; ++c) EXPECT_NEAR(j["F0"][c].get<double>(), gold["F0"][c].get<double>(), 1e-9);
    }
}

TEST_F(Cli, TwoRunsAreByteIdentical) {
    const Result a = run("show Au --json"), b = run("show Au --json");
    EXPECT_EQ(a.out, b.out);
    EXPECT_EQ(run("list --json").out, run("list --json").out);
}

TEST_F(Cli, ListCoversTheWholeCatalog) {
    const Result r = run("list --json");
    ASSERT_EQ(r.exit_code, 0) << r.err;
    const auto j = nlohmann::json::parse(r.out);
    EXPECT_EQ(j.size(), metalfit::test::catalog_material_count());
    for (const auto& m : j) {
        EXPECT_TRUE(m["covers_360_830"].get<bool>()) << m["id"];
        EXPECT_GT(m["points_360_830"].get<int>(), 0) << m["id"];
    }
}

TEST_F(Cli, MalformedFilesExitWithCode3AndOneLineNamingTheFile) {
    for (const char* name : {"bad-non-numeric.yml", "bad-negative-k.yml", "bad-empty-data.yml", "bad-no-data.yml",
                             "bad-unknown-type.yml", "bad-truncated.yml", "bad-short-range.yml",
                             "bad-wrong-columns.yml", "bad-header.csv", "bad-row.csv", "bad-negative-k.csv"}) {
        const Result r = run("show '" + kFixtures + "/" + name + "' --json");
        EXPECT_EQ(r.exit_code, 3) << name << ": " << r.err;
        expect_one_line_error(r, name);
    }
}

TEST_F(Cli, UsageErrorsExitWithCode2) {
    expect_one_line_error(run("show unobtainium"), "unobtainium");
    EXPECT_EQ(run("show unobtainium").exit_code, 2);
    EXPECT_EQ(run("show gold --source Nobody").exit_code, 2);
    EXPECT_EQ(run("show gold --cmf 1976").exit_code, 2);
    EXPECT_EQ(run("frobnicate").exit_code, 2);
    EXPECT_EQ(run("").exit_code, 2);
}

TEST_F(Cli, ColourConfigurationErrorsExitWithCode4) {
    const Result missing = run("show gold", "OCIO=/nonexistent/config.ocio");
    EXPECT_EQ(missing.exit_code, 4);
    expect_one_line_error(missing, "/nonexistent/config.ocio");
    const Result space = run("show gold --space 'No Such Space'");
    EXPECT_EQ(space.exit_code, 4);
    expect_one_line_error(space, "No Such Space");
}

TEST_F(Cli, OcioEnvironmentVariableTakesPrecedence) {
    const std::string config = std::string(METALFIT_TEST_DATA) + "/ocio/config.ocio";
    const Result r = run("show gold --json --ocio-config /nonexistent.ocio", "OCIO='" + config + "'");
    ASSERT_EQ(r.exit_code, 0) << r.err;
    EXPECT_EQ(nlohmann::json::parse(r.out)["provenance"]["ocio_config_origin"], "$OCIO");
    EXPECT_NE(r.err.find("--ocio-config is ignored"), std::string::npos);
    // Without $OCIO, the command-line config is used (and here it does not exist).
    EXPECT_EQ(run("show gold --ocio-config /nonexistent.ocio").exit_code, 4);
}

TEST_F(Cli, OutputFilesAreWrittenWholeOrNotAtAll) {
    const fs::path target = dir_ / "gold.json";
    const Result ok = run("show gold --json -o '" + target.string() + "'");
    ASSERT_EQ(ok.exit_code, 0) << ok.err;
    EXPECT_EQ(read_file(target), run("show gold --json").out);

    const fs::path nowhere = dir_ / "missing-dir" / "gold.json";
    const Result bad_dir = run("show gold --json -o '" + nowhere.string() + "'");
    EXPECT_EQ(bad_dir.exit_code, 3);
    EXPECT_FALSE(fs::exists(nowhere.parent_path()));

    // A failing computation leaves an existing output untouched and creates no temporary file.
    const std::string before = read_file(target);
    const Result failing = run("show '" + kFixtures + "/bad-row.csv' --json -o '" + target.string() + "'");
    EXPECT_EQ(failing.exit_code, 3);
    EXPECT_EQ(read_file(target), before);
    EXPECT_EQ(std::distance(fs::directory_iterator(dir_), fs::directory_iterator()), 1)  // gold.json (run_command
        << "a temporary file was left behind";                                          // removes its stdout/stderr)
}

// --- metalfit fit ---------------------------------------------------------------------------------------------

TEST_F(Cli, FitJsonRecordHasTheDocumentedShape) {
    const Result r = run("fit gold --json");
    ASSERT_EQ(r.exit_code, 0) << r.err;
    const auto j = nlohmann::json::parse(r.out);
    EXPECT_EQ(j["schema"], "metalfit.fit/1");
    const auto& p = j["provenance"];
    EXPECT_EQ(p["nodes"], 128);
    EXPECT_EQ(p["metric"], "rel");
    EXPECT_EQ(p["weight"], "uniform");
    EXPECT_EQ(p["cmf"], "CIE 1931 2°");
    EXPECT_EQ(p["illuminant"], "D65");
    EXPECT_EQ(p["color_space"], "Linear Rec.709 (sRGB)");
    EXPECT_EQ(p["ocio_config"]["sha256"].get<std::string>().size(), 64u);
    EXPECT_FALSE(p["metalfit_version"].get<std::string>().empty());

    const auto& gold = j["materials"]["Au"];
    // The data file's digest is the one show reports.
    EXPECT_EQ(gold["data"]["sha256"], nlohmann::json::parse(run("show gold --json").out)["provenance"]["sha256"]);
    EXPECT_EQ(gold["out_of_gamut_F0"], nlohmann::json::array({"red"}));
    std::vector<std::string> models;  // every registered model, as `metalfit models --json` lists them
    for (const auto& m : nlohmann::json::parse(run("models --json").out)) models.push_back(m["id"]);
    ASSERT_FALSE(models.empty());
    ASSERT_EQ(gold["models"].size(), models.size());
    std::vector<std::string> keys = {"rel_rms", "abs_rms", "max_rel", "max_abs", "de2000_mean", "de2000_max", "albedo_err"};
    std::sort(keys.begin(), keys.end());  // nlohmann::json iterates keys sorted
    for (const auto& id : models) {
        SCOPED_TRACE(id);
        const auto& m = gold["models"][id];
        const auto& fit = m["fit"];
        std::vector<std::string> metric_keys;
        for (const auto& [key, value] : fit["metrics"].items()) metric_keys.push_back(key);
        EXPECT_EQ(metric_keys, keys);
        for (const auto& [name, values] : fit["params"].items()) EXPECT_EQ(values.size(), 3u) << name;
        EXPECT_EQ(fit["params"].size(), m["parameters"].size());
        EXPECT_EQ(fit["solver"]["termination"].size(), 3u);
        EXPECT_EQ(fit["metrics"]["rel_rms"].size(), 3u);
        EXPECT_TRUE(fit["metrics"]["de2000_max"].is_number());
        // "closed" is the best closed form, or says why none is defined.
        const auto& closed = m["closed"];
        ASSERT_TRUE(closed.contains("params") != closed.contains("undefined")) << closed.dump();
        if (closed.contains("params")) {
            for (int c = 0; c < 3; ++c)
                EXPECT_LE(fit["metrics"]["rel_rms"][c].get<double>(), closed["metrics"]["rel_rms"][c].get<double>() + 1e-12);
        }
    }
    // F0 above 1 is kept by the models whose F0 is a free parameter.
    EXPECT_GT(gold["models"]["schlick"]["fit"]["params"]["F0"][0].get<double>(), 1.0);
    EXPECT_GT(gold["models"]["f82-tint"]["fit"]["params"]["F0"][0].get<double>(), 1.0);
}

TEST_F(Cli, ExportIntoANewFolderGivenWithATrailingSlash) {
    // The README's example: `-o gold/` names the folder gold, which does not exist yet.
    const Result r = run("export gold --model f82-tint --format glsl,mtlx -o '" + (dir_ / "gold").string() + "/'");
    ASSERT_EQ(r.exit_code, 0) << r.err;
    EXPECT_TRUE(fs::is_regular_file(dir_ / "gold" / "glsl" / "metalfit_models.glsl"));
    EXPECT_TRUE(fs::is_regular_file(dir_ / "gold" / "mtlx" / "metalfit_au_f82_tint.mtlx"));
}

TEST_F(Cli, UnknownCommandAndMissingMaterialSayWhatIsWrong) {
    for (const char* args : {"shwo gold", "--data-dir '" METALFIT_TEST_DATA "' shwo"}) {
        const Result r = run(args);
        EXPECT_EQ(r.exit_code, 2) << args;
        expect_one_line_error(r, "unknown command 'shwo'");
        EXPECT_NE(r.err.find("show"), std::string::npos) << r.err;  // the commands are listed
    }
    for (const char* command : {"fit", "export --model f82-tint --format glsl -o x"}) {
        const Result neither = run(command);
        EXPECT_EQ(neither.exit_code, 2) << command;
        expect_one_line_error(neither, "give a material (catalog name or file), or --all");
        EXPECT_EQ(neither.err.find("not both"), std::string::npos) << neither.err;
    }
    const Result both = run("fit Au --all");
    EXPECT_EQ(both.exit_code, 2);
    expect_one_line_error(both, "not both");
    EXPECT_FALSE(fs::exists(dir_ / "x"));
}

TEST_F(Cli, FitSummaryRowsAreTheRecordsWorstChannels) {
    // The Markdown summary and the JSON record are written by different code from the same fits: each cell of the
    // summary must be 100 × the largest rel_rms channel of the record, to two decimals.
    const fs::path summary = dir_ / "summary.md";
    const Result r = run("fit Zn --model schlick,lazanyi-comp,f82-tint --json --summary '" + summary.string() + "'");
    ASSERT_EQ(r.exit_code, 0) << r.err;
    const auto record = nlohmann::json::parse(r.out)["materials"]["Zn"]["models"];
    const auto worst = [](const nlohmann::json& metrics) -> std::string {
        if (metrics.is_null()) return "—";
        double w = 0;
        for (const auto& v : metrics["rel_rms"]) {
            if (v.is_null()) return "—";
            w = std::max(w, v.get<double>());
        }
        char text[32];
        std::snprintf(text, sizeof text, "%.2f", 100 * w);
        return text;
    };
    std::string row = "| Zn |", median = "| **median fit** |";
    for (const char* model : {"schlick", "lazanyi-comp", "f82-tint"}) {
        const auto& m = record[model];
        row += " " + worst(m["fit"]["metrics"]) + " / " + worst(m["closed"].contains("metrics") ? m["closed"]["metrics"] : nlohmann::json()) + " |";
        median += " " + worst(m["fit"]["metrics"]) + " |";  // one material: the median is its value
    }
    const std::string text = read_file(summary);
    EXPECT_NE(text.find("| material | schlick | lazanyi-comp | f82-tint |\n"), std::string::npos) << text;
    EXPECT_NE(text.find(row + "\n"), std::string::npos) << row << "\n" << text;
    EXPECT_NE(text.find(median + "\n"), std::string::npos) << median << "\n" << text;
}

TEST_F(Cli, FitRunsAreByteIdenticalWhateverTheThreads) {
    const Result a = run("fit --all --model schlick,f82-tint --json -j 1");
    const Result b = run("fit --all --model schlick,f82-tint --json -j 2");
    ASSERT_EQ(a.exit_code, 0) << a.err;
    EXPECT_EQ(a.out, b.out);
    EXPECT_EQ(nlohmann::json::parse(a.out)["materials"].size(), metalfit::test::catalog_material_count());
    EXPECT_EQ(run("fit Cu --json").out, run("fit Cu --json").out);
}

TEST_F(Cli, FitOptionsReachTheRecord) {
    const Result r = run("fit Al --model f82-tint,schlick --metric abs --weight cosine --nodes 64 --space ACEScg --json");
    ASSERT_EQ(r.exit_code, 0) << r.err;
    const auto j = nlohmann::json::parse(r.out);
    EXPECT_EQ(j["provenance"]["metric"], "abs");
    EXPECT_EQ(j["provenance"]["weight"], "cosine");
    EXPECT_EQ(j["provenance"]["nodes"], 64);
    EXPECT_EQ(j["provenance"]["color_space"], "ACEScg");
    const auto& models = j["materials"]["Al"]["models"];
    ASSERT_EQ(models.size(), 2u);
    EXPECT_LT(r.out.find("\"f82-tint\""), r.out.find("\"schlick\""));  // the order asked for
    const auto base = nlohmann::json::parse(run("fit Al --model schlick --json").out);
    EXPECT_NE(models["schlick"]["fit"]["params"], base["materials"]["Al"]["models"]["schlick"]["fit"]["params"]);
}

TEST_F(Cli, FitHumanOutputIsOneTablePerMaterial) {
    const Result r = run("fit gold --model f82-tint,lazanyi-comp");
    ASSERT_EQ(r.exit_code, 0) << r.err;
    EXPECT_NE(r.out.find("gold (Au"), std::string::npos) << r.out;
    EXPECT_NE(r.out.find("out of gamut, kept"), std::string::npos);
    EXPECT_NE(r.out.find("closed r1-r82"), std::string::npos);
    EXPECT_NE(r.out.find("lazanyi-comp"), std::string::npos);
    EXPECT_EQ(r.out.find("schlick "), std::string::npos) << "only the models asked for";
}

TEST_F(Cli, FitErrorsAreOneLineWithTheirExitCode) {
    const Result unknown_model = run("fit gold --model schlick,nope");
    EXPECT_EQ(unknown_model.exit_code, 2);
    expect_one_line_error(unknown_model, "f82-tint");  // lists the known models
    EXPECT_EQ(run("fit").exit_code, 2);
    EXPECT_EQ(run("fit gold --all").exit_code, 2);
    EXPECT_EQ(run("fit gold --nodes 1").exit_code, 2);
    EXPECT_EQ(run("fit gold --metric rms").exit_code, 2);
    const Result bad_file = run("fit '" + kFixtures + "/bad-row.csv'");
    EXPECT_EQ(bad_file.exit_code, 3);
    expect_one_line_error(bad_file, "bad-row.csv");
}

TEST_F(Cli, FitOfAMaterialThatReflectsNothingNeedsTheAbsoluteMetric) {
    // n = 1, k = 0: no interface, R = 0 for every angle, so the relative error is undefined.
    const std::string vacuum = kFixtures + "/fit-vacuum.csv";
    const Result rel = run("fit '" + vacuum + "' --model schlick");
    EXPECT_EQ(rel.exit_code, 3);
    expect_one_line_error(rel, "abs error metric");
    EXPECT_NE(rel.err.find("fit-vacuum.csv"), std::string::npos);

    const Result abs = run("fit '" + vacuum + "' --model schlick,conductor-rgb --metric abs --json");
    ASSERT_EQ(abs.exit_code, 0) << abs.err;
    const auto record = nlohmann::json::parse(abs.out);
    const auto& models = record["materials"]["fit-vacuum"]["models"];
    EXPECT_TRUE(models["schlick"]["fit"]["metrics"]["rel_rms"][0].is_null());  // undefined, written as null
    EXPECT_LT(models["conductor-rgb"]["fit"]["metrics"]["abs_rms"][0].get<double>(), 1e-6);
}

TEST_F(Cli, FitOutputIsWrittenWholeOrNotAtAll) {
    const fs::path target = dir_ / "fit.json";
    ASSERT_EQ(run("fit Ag --model schlick --json -o '" + target.string() + "'").exit_code, 0);
    const std::string before = read_file(target);
    EXPECT_EQ(before, run("fit Ag --model schlick --json").out);
    EXPECT_EQ(run("fit Ag --model nope --json -o '" + target.string() + "'").exit_code, 2);
    EXPECT_EQ(run("fit Ag --model schlick --json -o '" + (dir_ / "no" / "fit.json").string() + "'").exit_code, 3);
    EXPECT_EQ(read_file(target), before);
    EXPECT_FALSE(fs::exists(dir_ / "no"));
}

}  // namespace

// ---- stdout write errors (issue 13, item 5) ---------------------------------------------------------------------

TEST(CliStdout, AFullStdoutIsAnErrorNotASilentSuccess) {
    for (const char* args : {"list", "show gold", "models", "show gold --json"}) {
        const std::string command = "env OCIO= '" METALFIT_EXE "' " + std::string(args) + " >/dev/full 2>/dev/null";
        const int status = std::system(command.c_str());
        ASSERT_TRUE(WIFEXITED(status)) << args;
        EXPECT_EQ(WEXITSTATUS(status), 3) << args;
    }
    const std::string err_file = ::testing::TempDir() + "metalfit-stdout-err.txt";
    const std::string command = "env OCIO= '" METALFIT_EXE "' list >/dev/full 2>'" + err_file + "'";
    std::system(command.c_str());
    const std::string err = metalfit::test::read_file(err_file);
    EXPECT_TRUE(err.starts_with("metalfit: cannot write to standard output")) << err;
    EXPECT_EQ(std::count(err.begin(), err.end(), '\n'), 1) << err;
    std::filesystem::remove(err_file);
}

// ---- Library output (issue 13, item 10) and bad data through the CLI (item 2) ------------------------------------

TEST_F(Cli, CeresPrintsNothingOnAFitWhereResidualsFailToEvaluate) {
    // n = 0, k = 5: Ceres' residual evaluation fails at some starts and glog printed 151 lines
    std::ofstream(dir_ / "n0k5.csv") << "wavelength_nm,n,k\n300,0,5\n900,0,5\n";
    const Result r = run("fit '" + (dir_ / "n0k5.csv").string() + "'");
    EXPECT_EQ(r.exit_code, 0) << r.err;
    EXPECT_EQ(r.err, "");
}

TEST_F(Cli, ZeroIndexOverABandIsBadInputForEveryCommand) {
    std::ofstream(dir_ / "zero.csv") << "wavelength_nm,n,k\n400,0.2,3\n500,0,0\n600,0,0\n700,0.3,4\n";
    for (const char* command : {"fit --metric abs", "show"}) {
        const Result r = run(std::string(command) + " '" + (dir_ / "zero.csv").string() + "'");
        EXPECT_EQ(r.exit_code, 3) << command << ": " << r.err;
        expect_one_line_error(r, "zero.csv:3: n = k = 0");
    }
}
