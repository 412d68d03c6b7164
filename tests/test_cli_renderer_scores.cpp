// End-to-end tests of `metalfit table METAL --film FILM --thickness … --renderers` (docs/cli.md, the oxide colour
// chart; docs/colour.md, "What renderers draw for a thin film"): the truth it scores against is `show --film`'s stack,
// the rows are one per thickness and renderer, d = 0 is the bare metal's conductor-rgb fit for MaterialX, and bad
// combinations are one line, exit 2, nothing written.
#include <gtest/gtest.h>

#include <nlohmann/json.hpp>

#include <algorithm>
#include <cmath>
#include <map>
#include <sstream>
#include <string>
#include <vector>

#include "test_support.hpp"

namespace {

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

}  // namespace
