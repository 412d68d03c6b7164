// End-to-end tests of --film and --coat (docs/cli.md, "Layers"): show and fit on a stack, the stack in the records,
// the limits through the executable, and bad input (one line naming the option or file, its exit code, nothing
// written).
#include <gtest/gtest.h>

#include <nlohmann/json.hpp>

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <fstream>
#include <string>

#include "test_support.hpp"

namespace {

namespace fs = std::filesystem;
using Result = metalfit::test::CommandResult;
using metalfit::test::Contains;

class CliLayers : public ::testing::Test {
protected:
    Result run(const std::string& args) const {
        return metalfit::test::run_command(metalfit::test::kMetalfitExe, args, scratch_.path(), "OCIO=");
    }
    fs::path path(const std::string& name) const { return scratch_.path() / name; }

    // A clear oxide table of n = 2.0 + 0.1·(λ/1000 µm) over [first_nm, last_nm], k = 0, as CSV.
    fs::path oxide_csv(const std::string& name, int first_nm, int last_nm) const {
        const fs::path file = path(name);
        std::ofstream out(file);
        out << "wavelength_nm,n,k\n";
        for (int nm = first_nm; nm <= last_nm; nm += 10) out << nm << "," << 2.0 + 0.1 * nm / 1000.0 << ",0\n";
        return file;
    }

    static void expect_one_line_error(const Result& r, int code, const std::string& must_contain) {
        EXPECT_EQ(r.exit_code, code) << r.err;
        EXPECT_EQ(std::count(r.err.begin(), r.err.end(), '\n'), 1) << r.err;
        EXPECT_TRUE(Contains(r.err, must_contain));
        EXPECT_TRUE(r.out.empty()) << r.out;
    }

    static double max_difference(const nlohmann::json& a, const nlohmann::json& b) {
        double d = 0;
        for (int c = 0; c < 3; ++c) d = std::max(d, std::abs(a[c].get<double>() - b[c].get<double>()));
        return d;
    }

    metalfit::test::TempDir scratch_;
};

TEST_F(CliLayers, ShowNamesTheWholeStackAndItChangesTheColour) {
    const Result bare = run("show Ti --json");
    ASSERT_EQ(bare.exit_code, 0) << bare.err;
    const Result r = run("show Ti --film TiO2:80nm --coat 1.5 --json");
    ASSERT_EQ(r.exit_code, 0) << r.err;
    const auto j = nlohmann::json::parse(r.out), b = nlohmann::json::parse(bare.out);
    EXPECT_EQ(j["material"], "Ti");
    const auto& stack = j["provenance"]["stack"];
    EXPECT_EQ(stack["film"]["material"], "TiO2");
    EXPECT_EQ(stack["film"]["source"], "Siefke");
    EXPECT_EQ(stack["film"]["thickness_nm"], 80.0);
    EXPECT_EQ(stack["film"]["sha256"].get<std::string>().size(), 64u);
    EXPECT_TRUE(Contains(stack["film"]["file"].get<std::string>(), "films/TiO2/Siefke.yml"));
    EXPECT_EQ(stack["coat"]["source"], "constant");
    EXPECT_TRUE(stack["coat"]["thickness_nm"].is_null());
    EXPECT_EQ(stack["description"], "titanium under a coat n = 1.5 over a TiO2 (Siefke) film of 80 nm");
    EXPECT_GT(max_difference(j["F0"], b["F0"]), 0.05);  // an interference colour, not a small correction
    EXPECT_FALSE(b["provenance"].contains("stack"));    // bare records keep their keys
    const Result text = run("show Ti --film TiO2:0.08um");
    ASSERT_EQ(text.exit_code, 0) << text.err;
    EXPECT_TRUE(Contains(text.out, "  stack       titanium under a TiO2 (Siefke) film of 80 nm\n"));
}

TEST_F(CliLayers, NoFilmAndACoatOfIndexOneAreTheBareMetal) {
    const auto bare = nlohmann::json::parse(run("show Au --json").out);
    for (const char* layers : {"--film 2.2:0nm", "--coat 1", "--coat 1 --film TiO2:0nm"}) {
        const Result r = run(std::string("show Au --json ") + layers);
        ASSERT_EQ(r.exit_code, 0) << layers << ": " << r.err;
        const auto j = nlohmann::json::parse(r.out);
        for (const char* key : {"F0", "F82"})
            EXPECT_LT(max_difference(j[key], bare[key]), 1e-12) << layers << " " << key;
        for (const char* mu : {"0.5", "0.25", "0.1"})
            EXPECT_LT(max_difference(j["R"][mu], bare["R"][mu]), 1e-12) << layers;
    }
}

TEST_F(CliLayers, ACoatLowersGoldsNormalReflectanceAndKeepsGrazingAtOne) {
    const auto bare = nlohmann::json::parse(run("show Au --json").out);
    const Result r = run("show Au --coat 1.5 --json");
    ASSERT_EQ(r.exit_code, 0) << r.err;
    const auto j = nlohmann::json::parse(r.out);
    for (int c = 0; c < 3; ++c) EXPECT_LT(j["F0"][c].get<double>(), bare["F0"][c].get<double>()) << c;
}

TEST_F(CliLayers, FitRecordsTheStackAndAUserFileFilm) {
    const fs::path oxide = oxide_csv("my-oxide.csv", 300, 900);
    const Result r = run("fit Ti --film '" + oxide.string() +
                         ":120nm' --coat PMMA:20um --extrapolate --model f82-tint,schlick --json");
    ASSERT_EQ(r.exit_code, 0) << r.err;
    const auto j = nlohmann::json::parse(r.out);
    const auto& data = j["materials"]["Ti"]["data"];
    EXPECT_EQ(data["stack"]["film"]["material"], "my-oxide");
    EXPECT_EQ(data["stack"]["film"]["file"], oxide.string());
    EXPECT_EQ(data["stack"]["film"]["thickness_nm"], 120.0);
    EXPECT_EQ(data["stack"]["coat"]["material"], "PMMA");
    EXPECT_EQ(data["stack"]["coat"]["thickness_nm"], 20000.0);
    // PMMA's formula starts at 404.7 nm: --extrapolate holds it, and says so.
    const auto warnings = j["materials"]["Ti"]["warnings"].dump();
    EXPECT_TRUE(Contains(warnings, "coat PMMA (Szczurowski): n held at its 404.7 nm value over 360–404.7 nm"))
        << warnings;
    const Result human = run("fit Ti --film TiO2:80nm --model schlick");
    ASSERT_EQ(human.exit_code, 0) << human.err;
    EXPECT_TRUE(Contains(human.out, "  stack: titanium under a TiO2 (Siefke) film of 80 nm\n"));
    // Without layers the record has no stack.
    EXPECT_FALSE(
        nlohmann::json::parse(run("fit Ti --model schlick --json").out)["materials"]["Ti"]["data"].contains("stack"));
}

TEST_F(CliLayers, BadThicknessesAndIndicesAreOneLineExitThreeAndWriteNothing) {
    const fs::path out = path("out.json");
    struct Bad {
        std::string args, message;
    };
    for (const Bad& bad :
         {Bad{"--film 2.2:-5nm", "--film 2.2:-5nm: thickness -5 nm is negative"},
          Bad{"--film TiO2:nannm", "--film TiO2:nannm: thickness nan is not a finite number"},
          Bad{"--film TiO2:infum", "is not a finite number"},
          Bad{"--film TiO2:2.5um",
              "--film TiO2:2.5um: thickness 2500 nm is beyond 2 µm, where a film is no longer coherent"},
          Bad{"--coat 0.8", "--coat 0.8: index 0.8 is below 1"},
          Bad{"--coat 1.5:-1um", "--coat 1.5:-1um: thickness -1000 nm is negative"},
          Bad{"--film nan:80nm", "--film nan:80nm: index nan is not a finite number"}}) {
        for (const char* command : {"show", "fit"}) {
            const Result r = run(std::string(command) + " Ti " + bad.args + " -o '" + out.string() + "'");
            expect_one_line_error(r, 3, bad.message);
            EXPECT_FALSE(fs::exists(out)) << command << " " << bad.args;
        }
    }
}

TEST_F(CliLayers, AFilmTableNotCoveringTheColourRangeNamesWhatIsMissing) {
    const fs::path narrow = oxide_csv("narrow.csv", 400, 800);
    const fs::path out = path("out.json");
    for (const char* command : {"show", "fit"}) {
        const Result r =
            run(std::string(command) + " Au --film '" + narrow.string() + ":100nm' -o '" + out.string() + "'");
        expect_one_line_error(
            r, 3,
            narrow.string() +
                ": DATA: film n covers 400–800 nm, but colour needs 360–830 nm: 360–400 nm and 800–830 nm missing (--extrapolate");
        EXPECT_FALSE(fs::exists(out));
    }
    const Result held = run("show Au --film '" + narrow.string() + ":100nm' --extrapolate --json");
    ASSERT_EQ(held.exit_code, 0) << held.err;
    EXPECT_TRUE(Contains(held.err, "film narrow (narrow.csv): n held at its 400 nm value over 360–400 nm"));
}

TEST_F(CliLayers, ACoatTableBelowIndexOneIsRefusedNamingTheWavelength) {
    const fs::path thin = path("thin.csv");
    {
        std::ofstream out(thin);
        out << "wavelength_nm,n,k\n300,1.2,0\n500,0.95,0\n900,1.2,0\n";
    }
    const fs::path out = path("out.json");
    for (const char* command : {"show", "fit"}) {
        const Result r = run(std::string(command) + " Au --coat '" + thin.string() + "' -o '" + out.string() + "'");
        expect_one_line_error(r, 3, thin.string() + ": DATA: coat n = ");
        EXPECT_TRUE(Contains(r.err, "is below 1: a coat is a dielectric at least as dense as air"));
        EXPECT_FALSE(fs::exists(out));
    }
}

TEST_F(CliLayers, UnknownOrIncompleteLayersAreUsageErrors) {
    expect_one_line_error(run("show Ti --film TiO2"), 2,
                          "--film TiO2: give the film's thickness with a unit (TiO2:80nm)");
    expect_one_line_error(run("show Ti --film TiO2:80"), 2, "--film TiO2:80: give the thickness's unit (80nm or um)");
    expect_one_line_error(run("show Ti --film unobtainium:80nm"), 2,
                          "unknown film or coat material 'unobtainium' (known: TiO2,");
    expect_one_line_error(run("show Cu --film Cu2O:50nm"), 2, "Cu2O has no visible data in refractiveindex.info");
    expect_one_line_error(run("show Cu --film CuO:50nm"), 2, "CuO has no visible data");
    expect_one_line_error(run("show Ti --coat 1.5:80"), 2, "give the thickness's unit");
}

TEST_F(CliLayers, EveryShippedFilmAndCoatLoads) {
    std::ifstream in(metalfit::test::kData / "films.json");
    const auto films = nlohmann::json::parse(in);
    for (const auto& m : films["materials"]) {
        const std::string id = m["id"];
        const bool covers = id != "PMMA" && id != "polycarbonate";  // docs/data.md: no polymer covers 360 nm
        const Result r = run("show Al --film " + id + ":100nm --json" + (covers ? "" : " --extrapolate"));
        ASSERT_EQ(r.exit_code, 0) << id << ": " << r.err;
        EXPECT_EQ(nlohmann::json::parse(r.out)["provenance"]["stack"]["film"]["material"], id);
        if (!covers) expect_one_line_error(run("show Al --coat " + id), 3, "--extrapolate");
    }
}

}  // namespace
