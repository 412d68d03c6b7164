// End-to-end tests of `metalfit table METAL --film FILM --thickness … --renderers` (docs/cli.md, the oxide colour
// chart; docs/colour.md, "What renderers draw for a thin film"): the truth it scores against is `show --film`'s stack,
// the rows are one per thickness and renderer, d = 0 is the bare metal's conductor-rgb fit for MaterialX, bad
// combinations are one line, exit 2, nothing written, and `report --film` carries the same scores per material.
#include <gtest/gtest.h>

#include <nlohmann/json.hpp>

#include <algorithm>
#include <cmath>
#include <map>
#include <sstream>
#include <string>
#include <vector>

#include "test_support.hpp"

namespace test_cli_renderer_scores {

using Result = metalfit::test::CommandResult;
using metalfit::test::Contains;

class CliRendererScores : public ::testing::Test {
protected:
    Result run(const std::string& args) const {
        return metalfit::test::run_command(metalfit::test::kMetalfitExe, args, scratch_.path(), "OCIO=");
    }
    metalfit::test::TempDir scratch_;
};

std::vector<std::string> split(const std::string& line, char sep) {
    std::vector<std::string> parts;
    std::stringstream in(line);
    for (std::string part; std::getline(in, part, sep);) parts.push_back(part);
    return parts;
}

TEST_F(CliRendererScores, ScoresEachRendererAgainstTheStackShowDescribes) {
    const Result r = run("table Ti --film TiO2 --thickness 0:80:80nm --renderers --format csv");
    ASSERT_EQ(r.exit_code, 0) << r.err;
    std::stringstream in(r.out);
    std::string line;
    std::getline(in, line);
    const std::vector<std::string> header = split(line, ',');
    std::vector<std::map<std::string, std::string>> rows;
    while (std::getline(in, line)) {
        const std::vector<std::string> cells = split(line, ',');
        ASSERT_EQ(cells.size(), header.size()) << line;
        std::map<std::string, std::string> row;
        for (std::size_t i = 0; i < cells.size(); ++i) row[header[i]] = cells[i];
        rows.push_back(row);
    }
    ASSERT_EQ(rows.size(), 10u);  // two thicknesses × five renderers
    EXPECT_EQ(rows[0]["renderer"], "materialx");
    EXPECT_EQ(rows[1]["renderer"], "materialx-nk");
    EXPECT_EQ(rows[2]["renderer"], "belcour-barla");
    EXPECT_EQ(rows[3]["renderer"], "belcour-barla-working");
    EXPECT_EQ(rows[4]["renderer"], "airy-3");
    for (const auto& [d, first] : {std::pair<const char*, std::size_t>{"0", 0}, {"80", 5}}) {
        const auto shown = nlohmann::json::parse(run(std::string("show Ti --film TiO2:") + d + "nm --json").out);
        for (int c = 0; c < 3; ++c) {
            const char* channel[3] = {"r", "g", "b"};
            const double truth = std::stod(rows[first]["truth_f0_" + std::string(channel[c])]);
            EXPECT_NEAR(truth, shown["F0"][c].get<double>(), 1e-7) << d << " nm";
        }
    }
    // At d = 0 MaterialX draws the conductor-rgb fit: under 0.1 ΔE2000 where the film of 80 nm is several off.
    EXPECT_LT(std::stod(rows[0]["de2000_mean"]), 0.1);
    for (std::size_t i = 5; i < 10; ++i) EXPECT_GT(std::stod(rows[i]["de2000_mean"]), 0.5) << rows[i]["renderer"];

    const Result md = run("table Ti --film TiO2 --thickness 0:80:80nm --renderers");
    ASSERT_EQ(md.exit_code, 0) << md.err;
    EXPECT_TRUE(Contains(md.out, "Mean over the 2 thicknesses"));
}

TEST_F(CliRendererScores, BadCombinationsAreOneLineAndExit2) {
    for (const char* args :
         {"table Ti --film TiO2 --renderers", "table Ti --film TiO2 --thickness 80nm --renderers --coat 1.5",
          "table Ti --film TiO2 --thickness 80nm --renderers --versus 2.488",
          "table Ti --film TiO2 --thickness 80nm --renderers --format html"}) {
        const Result r = run(args);
        EXPECT_EQ(r.exit_code, 2) << args << ": " << r.err;
        EXPECT_EQ(std::count(r.err.begin(), r.err.end(), '\n'), 1) << r.err;
        EXPECT_TRUE(Contains(r.err, "--renderers")) << r.err;
        EXPECT_TRUE(r.out.empty()) << r.out;
    }
}

// A filmed material's report carries, beside its stack, what `table --renderers` scores at the film's thickness: the
// record the table writes for that metal and thickness, value for value (each material its own, not the first's);
// under a coat the reason instead of scores; a bare or only coated material none.
TEST_F(CliRendererScores, AFilmedMaterialsReportCarriesTheTablesScoresAtItsThickness) {
    const auto folder = [this](const char* name) { return "'" + (scratch_.path() / name).string() + "'"; };
    const Result report = run("report Ti,Au --film TiO2:80nm --model schlick --renders off -o " + folder("filmed"));
    ASSERT_EQ(report.exit_code, 0) << report.err;
    const auto record = nlohmann::json::parse(metalfit::test::read_file(scratch_.path() / "filmed/report.json"));
    ASSERT_EQ(record["materials"].size(), 2u);
    for (const auto& material : record["materials"]) {
        const std::string id = material["id"].get<std::string>();
        const Result table = run("table " + id + " --film TiO2 --thickness 80nm --renderers --format json");
        ASSERT_EQ(table.exit_code, 0) << table.err;
        const auto scores = nlohmann::json::parse(table.out);
        ASSERT_TRUE(material.contains("renderer_film")) << id;
        const auto& shown = material["renderer_film"];
        EXPECT_EQ(shown["metal"], id);
        ASSERT_EQ(shown["rows"].size(), 1u) << id;
        EXPECT_EQ(shown["rows"][0]["thickness_nm"].get<double>(), 80.0);
        EXPECT_EQ(shown, scores) << id << ": the report's scores are not the table's";
    }
    EXPECT_NE(record["materials"][0]["renderer_film"]["rows"], record["materials"][1]["renderer_film"]["rows"]);

    const Result coated =
        run("report Ti --film TiO2:80nm --coat 1.5 --model schlick --renders off -o " + folder("coated"));
    ASSERT_EQ(coated.exit_code, 0) << coated.err;
    const auto under_coat = nlohmann::json::parse(metalfit::test::read_file(scratch_.path() / "coated/report.json"));
    const auto& not_scored = under_coat["materials"][0]["renderer_film"];
    ASSERT_EQ(not_scored.size(), 1u) << not_scored;
    EXPECT_TRUE(Contains(not_scored["not_scored"].get<std::string>(), "coat")) << not_scored;

    for (const std::string layers : {"--coat 1.5", ""}) {
        const std::string args = "report Ti " + layers + " --model schlick --renders off -o " + folder("other");
        const Result r = run(args);
        ASSERT_EQ(r.exit_code, 0) << args << ": " << r.err;
        const auto other = nlohmann::json::parse(metalfit::test::read_file(scratch_.path() / "other/report.json"));
        EXPECT_FALSE(other["materials"][0].contains("renderer_film")) << args;
    }
}

}  // namespace test_cli_renderer_scores
