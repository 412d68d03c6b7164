// "Say what is wrong, always" (issue 29, item 4), through the real metalfit: colours an export writes outside
// [0, 1] (stderr, each text file's header, the export record), rational fits with a pole in [0, 1] (discarded; the
// best pole-free start kept) and --pin F0 against a parameter bound (refused for that channel, said).
#include <gtest/gtest.h>

#include "libfit/models/model.hpp"
#include "test_support.hpp"
#include <nlohmann/json.hpp>

#include <cmath>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <string>
#include <vector>

namespace test_cli_warnings {

namespace fs = std::filesystem;
using metalfit::test::Contains;
using metalfit::test::kMetalfitExe;
using metalfit::test::read_file;
using metalfit::test::run_command;
using metalfit::test::TempDir;
using Json = nlohmann::json;

std::vector<std::string> lines_with(const std::string& text, const std::string& needle) {
    std::vector<std::string> lines;
    std::istringstream in(text);
    for (std::string line; std::getline(in, line);)
        if (line.find(needle) != std::string::npos) lines.push_back(line);
    return lines;
}

// The smallest value of rational's denominator 1 + c mu + d mu^2 on a fine grid of [0, 1].
double denominator_minimum(double c, double d) {
    double minimum = 1;
    for (int i = 0; i <= 100000; ++i) {
        const double mu = i / 100000.0;
        minimum = std::min(minimum, 1 + c * mu + d * mu * mu);
    }
    return minimum;
}

TEST(ExportWarnings, ColoursOutsideTheUnitRangeAreSaidOnStderrInHeadersAndInTheRecord) {
    TempDir dir;
    const fs::path out = dir.path() / "out";
    const auto r =
        run_command(kMetalfitExe, "export Au --model f82-tint --format all -o '" + out.string() + "'", dir.path());
    ASSERT_EQ(r.exit_code, 0) << r.err;
    // Gold's f82-tint: F0 red ≈ 1.03 and tint green ≈ 1.003 in Linear Rec.709; OpenPBR writes them as base_color
    // and specular_color, MaterialX as color0 and color82.
    EXPECT_TRUE(Contains(r.err, "export: openpbr/metalfit_au_f82_tint.json: specular_color green = 1.00"));
    EXPECT_TRUE(Contains(r.err, "export: openpbr/metalfit_au_f82_tint.mtlx: base_color red = 1.03"));
    EXPECT_TRUE(Contains(r.err, "export: mtlx/metalfit_au_f82_tint.mtlx: color0 red = 1.03"));
    EXPECT_TRUE(Contains(r.err, "export: glsl/metalfit_au_f82_tint.glsl: F0 red = 1.03"));
    EXPECT_TRUE(Contains(r.err, "export: hlsl/metalfit_au_f82_tint.hlsl: tint green = 1.00"));
    EXPECT_TRUE(Contains(r.err, "export: cpp/metalfit_au_f82_tint.hpp: F0 red = 1.03"));
    const auto stderr_lines = lines_with(r.err, "outside [0, 1] (Au, f82-tint");
    // Every text format's header says it.
    for (const char* file :
         {"glsl/metalfit_au_f82_tint.glsl", "hlsl/metalfit_au_f82_tint.hlsl", "cpp/metalfit_au_f82_tint.hpp",
          "mtlx/metalfit_au_f82_tint.mtlx", "openpbr/metalfit_au_f82_tint.mtlx"})
        EXPECT_EQ(lines_with(read_file(out / file), "OUT OF RANGE: ").size() > 0, true) << file;
    EXPECT_TRUE(Contains(read_file(out / "glsl/metalfit_au_f82_tint.glsl"), "// OUT OF RANGE: F0 red = 1.03"));
    // The record lists every one of them, each a file of the folder and a value outside [0, 1].
    const Json record = Json::parse(read_file(out / "metalfit_export.json"));
    const Json& list = record["materials"]["Au"]["models"]["f82-tint"]["export"]["out_of_range"];
    ASSERT_TRUE(list.is_array());
    EXPECT_EQ(list.size(), stderr_lines.size());
    bool specular = false;
    for (const Json& e : list) {
        EXPECT_TRUE(fs::is_regular_file(out / e["file"].get<std::string>())) << e;
        const double v = e["value"];
        EXPECT_TRUE(v > 1 || v < 0) << e;
        specular = specular || (e["file"] == "openpbr/metalfit_au_f82_tint.json" &&
                                e["parameter"] == "specular_color" && e["channel"] == "green");
    }
    EXPECT_TRUE(specular) << list;
}

TEST(ExportWarnings, ClippedColoursAreNotOutOfRange) {
    TempDir dir;
    const fs::path out = dir.path() / "out";
    const auto r = run_command(
        kMetalfitExe, "export Au --model f82-tint --format json,glsl,openpbr --gamut clip -o '" + out.string() + "'",
        dir.path());
    ASSERT_EQ(r.exit_code, 0) << r.err;
    EXPECT_TRUE(lines_with(r.err, "outside [0, 1] (Au").empty()) << r.err;
    EXPECT_TRUE(lines_with(read_file(out / "glsl/metalfit_au_f82_tint.glsl"), "OUT OF RANGE").empty());
    const Json record = Json::parse(read_file(out / "metalfit_export.json"));
    EXPECT_EQ(record["materials"]["Au"]["models"]["f82-tint"]["export"]["out_of_range"], Json::array());
}

TEST(RationalPoles, ADenominatorWithARootInTheUnitIntervalIsInadmissible) {
    const metalfit::Model& rational = metalfit::find_model("rational");
    const std::vector<double> pole{-2.18, 1.18, -9997.98, 10000.0};  // η ≈ 1's fit before: roots at 1e-4 and 0.9997
    EXPECT_TRUE(Contains(rational.inadmissible(pole), "has a root in [0, 1]"));
    EXPECT_EQ(rational.inadmissible(std::vector<double>{0, 0, 0, 0}), "");
    EXPECT_EQ(rational.inadmissible(std::vector<double>{-2.35, 1.44, -46.08, 2406.7}), "");  // vertex above 0
    EXPECT_NE(rational.inadmissible(std::vector<double>{0, 0, -2, 0}), "");                  // root at 0.5
    EXPECT_NE(rational.inadmissible(std::vector<double>{0, 0, -1, 0}), "");                  // root at 1
    EXPECT_EQ(metalfit::find_model("schlick").inadmissible(std::vector<double>{0.5}), "");
}

TEST(RationalPoles, AnEtaNearOneFitIsPoleFreeAndExportsFiniteConstants) {
    TempDir dir;
    {
        std::ofstream csv(dir.path() / "eta1.csv");
        csv << "wavelength_nm,n,k\n";
        for (int nm = 360; nm <= 830; nm += 10) csv << nm << ",1.0,0.001\n";
    }
    const auto fit = run_command(
        kMetalfitExe, "fit '" + (dir.path() / "eta1.csv").string() + "' --model rational --json", dir.path());
    ASSERT_EQ(fit.exit_code, 0) << fit.err;
    const Json record = Json::parse(fit.out);
    const Json& params = record["materials"]["eta1"]["models"]["rational"]["fit"]["params"];
    for (int c = 0; c < 3; ++c) {
        const double cc = params["c"][c], d = params["d"][c];
        EXPECT_GT(denominator_minimum(cc, d), 0) << "channel " << c << ": c = " << cc << ", d = " << d;
    }
    const fs::path out = dir.path() / "out";
    const auto exported = run_command(kMetalfitExe,
                                      "export '" + (dir.path() / "eta1.csv").string() +
                                          "' --model rational --format json,glsl -o '" + out.string() + "'",
                                      dir.path());
    ASSERT_EQ(exported.exit_code, 0) << exported.err;
    const std::string glsl = read_file(out / "glsl/metalfit_eta1_rational.glsl");
    for (const char* bad : {"inf", "nan", "e+06", "e+07"}) EXPECT_FALSE(Contains(glsl, bad)) << bad << "\n" << glsl;
    const Json exported_record = Json::parse(read_file(out / "metalfit_export.json"));
    const Json& metrics = exported_record["materials"]["eta1"]["models"]["rational"]["export"]["metrics"];
    for (const Json& v : metrics["max_abs"]) EXPECT_LT(v.get<double>(), 1.0) << metrics;
}

TEST(PinF0, APinTheModelsBoundsForbidIsRefusedForThatChannelAndSaid) {
    TempDir dir;
    // Gold's red R(1) = 1.038 in Linear Rec.709: Gulbrandsen's r <= 0.99999 cannot hold it.
    const auto r = run_command(kMetalfitExe, "fit Au --model gulbrandsen --pin F0 --json", dir.path());
    ASSERT_EQ(r.exit_code, 0) << r.err;
    EXPECT_TRUE(Contains(r.err, "Au: gulbrandsen: red: --pin F0 refused: F(1) = R(1) = 1.03")) << r.err;
    EXPECT_TRUE(lines_with(r.err, "gulbrandsen: green").empty()) << r.err;
    const Json record = Json::parse(r.out);
    const Json& fit = record["materials"]["Au"]["models"]["gulbrandsen"]["fit"];
    ASSERT_TRUE(fit.contains("refused")) << fit;
    EXPECT_TRUE(Contains(fit["refused"][0].get<std::string>(), "the unpinned fit is kept")) << fit["refused"];
    EXPECT_TRUE(fit["refused"][1].is_null());
    EXPECT_TRUE(fit["refused"][2].is_null());
    // Every parameter inside Gulbrandsen's own bounds.
    for (const char* p : {"r", "g"})
        for (int c = 0; c < 3; ++c) {
            const double v = fit["params"][p][c];
            EXPECT_GE(v, 0.0) << p << c;
            EXPECT_LE(v, p == std::string("r") ? 0.99999 : 1.0) << p << c;
        }
    // The channels whose R(1) it can hold are pinned.
    EXPECT_NEAR(fit["err_f0"][1].get<double>(), 0.0, 1e-9);
}

}  // namespace test_cli_warnings
