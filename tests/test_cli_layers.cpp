// End-to-end tests of --film and --coat (docs/cli.md, "Layers"): show and fit on a stack, the stack in the records,
// the limits through the executable, and bad input (one line naming the option or file, its exit code, nothing
// written).
#include <gtest/gtest.h>

#include <nlohmann/json.hpp>

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <fstream>
#include <iterator>
#include <string>
#include <vector>

#include "test_support.hpp"

namespace test_cli_layers {

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
    // A file outside the database and the working folder: its name alone (docs/fit-record.md, Paths in records).
    EXPECT_EQ(data["stack"]["film"]["file"], "outside:my-oxide.csv");
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

// --- export, report and table take the layers too, and name the whole stack ---------------------------------------

TEST_F(CliLayers, ExportReportAndTableNameTheWholeStack) {
    const std::string stack = "titanium under a TiO2 (Siefke) film of 80 nm";
    const Result ex =
        run("export Ti --film TiO2:80nm --model f82-tint --format json,glsl -o '" + path("ex").string() + "'");
    ASSERT_EQ(ex.exit_code, 0) << ex.err;
    std::ifstream record_in(path("ex") / "metalfit_export.json");
    const auto record = nlohmann::json::parse(record_in);
    EXPECT_EQ(record["materials"]["Ti"]["data"]["stack"]["description"], stack);
    bool glsl_names_stack = false;
    for (const auto& entry : fs::recursive_directory_iterator(path("ex")))
        if (entry.path().extension() == ".glsl") {
            std::ifstream in(entry.path());
            const std::string text((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
            glsl_names_stack = glsl_names_stack || Contains(text, "stack: " + stack);
        }
    EXPECT_TRUE(glsl_names_stack);

    const Result report =
        run("report Ti --film TiO2:80nm --model f82-tint --renders off -o '" + path("report").string() + "'");
    ASSERT_EQ(report.exit_code, 0) << report.err;
    std::ifstream report_in(path("report") / "report.json");
    const auto rj = nlohmann::json::parse(report_in);
    const auto& material = rj["materials"][0];
    EXPECT_EQ(material["provenance"]["stack"]["description"], stack);
    // The report's F0 is the stack's, as show says.
    const auto shown = nlohmann::json::parse(run("show Ti --film TiO2:80nm --json").out);
    EXPECT_LT(max_difference(material["F0"], shown["F0"]), 1e-12);

    const Result table = run("table Ti,Au --film TiO2:80nm --format json");
    ASSERT_EQ(table.exit_code, 0) << table.err;
    const auto tj = nlohmann::json::parse(table.out);
    ASSERT_EQ(tj["materials"].size(), 2u);
    EXPECT_EQ(tj["materials"][0]["stack"]["description"], stack);
    EXPECT_LT(max_difference(tj["materials"][0]["F0"]["linear"], shown["F0"]), 1e-12);
    // The bare table keeps its keys.
    const auto bare = nlohmann::json::parse(run("table --format json").out);
    EXPECT_FALSE(bare["materials"][0].contains("stack"));
    const Result md = run("table Ti --coat 1.5");
    ASSERT_EQ(md.exit_code, 0) << md.err;
    EXPECT_TRUE(Contains(md.out, "stack: titanium under a coat n = 1.5"));
}

TEST_F(CliLayers, BadLayersOnExportReportAndTableAreOneLineExitThreeAndWriteNothing) {
    const fs::path out = path("out");
    for (const std::string command :
         {"export Ti --model f82-tint --format json", "report Ti --model f82-tint --renders off", "table Ti"}) {
        for (const char* bad : {"--film 2.2:-5nm", "--film TiO2:2.5um", "--coat 0.8"}) {
            const Result r = run(command + " " + bad + " -o '" + out.string() + "'");
            expect_one_line_error(r, 3, bad);
            EXPECT_FALSE(fs::exists(out)) << command << " " << bad;
        }
    }
    expect_one_line_error(run("table --format physicallybased --coat 1.5"), 2, "bare metals");
}

// --- named finishes (data/finishes.json) ----------------------------------------------------------------------------

TEST_F(CliLayers, NamedFinishesAreTheirMetalUnderTheirLayers) {
    struct Case {
        std::string finish, same;
    };
    for (const Case& c :
         {Case{"anodized-ti-80nm", "Ti --film TiO2:80nm"}, Case{"tempered-steel-straw", "Fe --film Fe3O4:20nm"},
          Case{"tempered-steel-blue", "Fe --film Fe3O4:60nm"}, Case{"lacquered-brass", "brass --coat 1.49"}}) {
        const Result r = run("show " + c.finish + " --json");
        ASSERT_EQ(r.exit_code, 0) << c.finish << ": " << r.err;
        const auto j = nlohmann::json::parse(r.out);
        const auto same = nlohmann::json::parse(run("show " + c.same + " --json").out);
        EXPECT_EQ(j["material"], c.finish);
        EXPECT_EQ(j["provenance"]["stack"]["finish"]["id"], c.finish);
        EXPECT_EQ(j["provenance"]["file"], same["provenance"]["file"]);
        EXPECT_EQ(max_difference(j["F0"], same["F0"]), 0.0) << c.finish;
        EXPECT_EQ(max_difference(j["F82"], same["F82"]), 0.0) << c.finish;
    }
    // By name and alias, on fit too; a finish takes no other layers.
    const Result fit = run("fit 'blued steel' --model schlick --json");
    ASSERT_EQ(fit.exit_code, 0) << fit.err;
    EXPECT_TRUE(nlohmann::json::parse(fit.out)["materials"].contains("tempered-steel-blue"));
    expect_one_line_error(run("show lacquered-brass --coat 1.5"), 2, "named finish with layers of its own");
    const Result list = run("list");
    EXPECT_TRUE(Contains(list.out, "anodized-ti-80nm")) << list.out;
    // In a report: its metal's catalog provenance and the finish.
    const Result report =
        run("report tempered-steel-blue --model schlick --renders off -o '" + path("report").string() + "'");
    ASSERT_EQ(report.exit_code, 0) << report.err;
    std::ifstream in(path("report") / "report.json");
    const auto m = nlohmann::json::parse(in)["materials"][0];
    EXPECT_EQ(m["id"], "tempered-steel-blue");
    EXPECT_EQ(m["provenance"]["kind"], "metal");
    EXPECT_EQ(m["provenance"]["stack"]["finish"]["id"], "tempered-steel-blue");
}

TEST_F(CliLayers, EveryShippedFinishLoadsAndStatesItsSources) {
    std::ifstream in(metalfit::test::kData / "finishes.json");
    const auto finishes = nlohmann::json::parse(in);
    ASSERT_GE(finishes["finishes"].size(), 4u);
    for (const auto& f : finishes["finishes"]) {
        const std::string id = f["id"];
        EXPECT_FALSE(f["sources"].empty()) << id;
        EXPECT_FALSE(f["note"].get<std::string>().empty()) << id;
        const Result r = run("show " + id + " --json");
        ASSERT_EQ(r.exit_code, 0) << id << ": " << r.err;
        EXPECT_EQ(nlohmann::json::parse(r.out)["provenance"]["stack"]["finish"]["name"], f["name"]);
    }
}

// --- the oxide colour chart ---------------------------------------------------------------------------------------

// The hue (degrees) and HSV saturation and value of an 8-bit display colour.
struct Hsv {
    double h = 0, s = 0, v = 0;
};
Hsv hsv(const nlohmann::json& rgb8) {
    const double r = rgb8[0].get<double>() / 255, g = rgb8[1].get<double>() / 255, b = rgb8[2].get<double>() / 255;
    const double mx = std::max({r, g, b}), mn = std::min({r, g, b}), c = mx - mn;
    Hsv out{0, mx > 0 ? c / mx : 0, mx};
    if (c <= 0) return out;
    if (mx == r)
        out.h = 60 * std::fmod((g - b) / c + 6, 6.0);
    else if (mx == g)
        out.h = 60 * ((b - r) / c + 2);
    else
        out.h = 60 * ((r - g) / c + 4);
    return out;
}

// The published names of anodizing colours, by hue: yellow/gold/bronze, purple/violet/magenta, blue; else none
// (pale or grey: "silver", "light blue" below the saturation threshold).
std::string colour_name(const Hsv& c) {
    if (c.s < 0.15) return "";
    if (c.h >= 20 && c.h < 75) return "yellow";
    if (c.h >= 270 || c.h < 20) return "purple";
    if (c.h >= 180 && c.h < 270) return "blue";
    return "green";
}

TEST_F(CliLayers, TitaniumsOxideColoursFollowThePublishedOrderWithThickness) {
    // Published order of anodized titanium with voltage (thickness): yellow/gold (bronze) - purple - blue - light
    // blue/silver - yellow - pink/purple - ... (carlesso.net, data/finishes.json): the colour names in order of
    // thickness, runs merged, must begin with that sequence.
    const Result r = run("table Ti --film TiO2 --thickness 0:300:2nm --format json");
    ASSERT_EQ(r.exit_code, 0) << r.err;
    const auto chart = nlohmann::json::parse(r.out);
    std::vector<std::string> order;
    std::vector<double> at;
    for (const auto& row : chart["rows"]) {
        const std::string name = colour_name(hsv(row["F0"]["display8"]));
        if (name.empty() || (!order.empty() && order.back() == name)) continue;
        order.push_back(name);
        at.push_back(row["thickness_nm"].get<double>());
    }
    std::string seen;
    for (std::size_t i = 0; i < order.size(); ++i) seen += order[i] + "@" + std::to_string(int(at[i])) + " ";
    const std::vector<std::string> published{"yellow", "purple", "blue", "yellow", "purple"};
    ASSERT_GE(order.size(), published.size()) << seen;
    EXPECT_TRUE(std::equal(published.begin(), published.end(), order.begin())) << seen;
}

TEST_F(CliLayers, TemperColoursOfIronFollowThePublishedOrderAndTheFinishesSitInIt) {
    // Temper colours of steel with temperature (thickness): faint yellow, straw, brown, purple, dark blue, light blue
    // (data/finishes.json's sources): Fe3O4 on iron, named by hue in order of thickness, runs merged.
    const Result r = run("table Fe --film Fe3O4 --thickness 0:100:2nm --format json");
    ASSERT_EQ(r.exit_code, 0) << r.err;
    std::vector<std::string> order;
    const auto chart = nlohmann::json::parse(r.out);
    for (const auto& row : chart["rows"]) {
        const std::string name = colour_name(hsv(row["F0"]["display8"]));
        if (!name.empty() && (order.empty() || order.back() != name)) order.push_back(name);
    }
    const std::vector<std::string> published{"yellow", "purple", "blue"};
    ASSERT_GE(order.size(), published.size());
    EXPECT_TRUE(std::equal(published.begin(), published.end(), order.begin()));
    // The straw finish is a yellow, the blue one a blue.
    const auto straw = nlohmann::json::parse(run("table tempered-steel-straw --format json").out);
    const auto blue = nlohmann::json::parse(run("table tempered-steel-blue --format json").out);
    EXPECT_EQ(colour_name(hsv(straw["materials"][0]["F0"]["display8"])), "yellow");
    EXPECT_EQ(colour_name(hsv(blue["materials"][0]["F0"]["display8"])), "blue");
}

TEST_F(CliLayers, ChartAtZeroIsTheBareMetalAndItsRowsAreTheStacks) {
    const Result r = run("table Ti --film TiO2 --thickness 0:100:20nm --versus 2.488 --format json");
    ASSERT_EQ(r.exit_code, 0) << r.err;
    const auto chart = nlohmann::json::parse(r.out);
    ASSERT_EQ(chart["rows"].size(), 6u);
    const auto bare = nlohmann::json::parse(run("show Ti --json").out);
    EXPECT_LT(max_difference(chart["rows"][0]["F0"]["linear"], bare["F0"]), 1e-12);
    EXPECT_LT(max_difference(chart["rows"][0]["F82"]["linear"], bare["F82"]), 1e-12);
    EXPECT_LT(chart["rows"][0]["de2000"]["F0"].get<double>(), 1e-9);  // no film: nothing to differ
    for (const int i : {2, 4}) {
        const auto& row = chart["rows"][i];
        const std::string d = std::to_string(20 * i) + "nm";
        EXPECT_EQ(row["thickness_nm"], 20.0 * i);
        const auto dispersive = nlohmann::json::parse(run("show Ti --film TiO2:" + d + " --json").out);
        EXPECT_LT(max_difference(row["F0"]["linear"], dispersive["F0"]), 1e-12) << d;
        EXPECT_LT(max_difference(row["F82"]["linear"], dispersive["F82"]), 1e-12) << d;
        // The --versus column is a film of constant index 2.488 (k = 0), as --film 2.488 computes it.
        const auto constant = nlohmann::json::parse(run("show Ti --film 2.488:" + d + " --json").out);
        EXPECT_LT(max_difference(row["versus"]["F0"]["linear"], constant["F0"]), 1e-12) << d;
        EXPECT_LT(max_difference(row["versus"]["F82"]["linear"], constant["F82"]), 1e-12) << d;
        EXPECT_GT(row["de2000"]["F0"].get<double>(), 0.0);
    }
    const auto& versus = chart["versus"];
    EXPECT_EQ(versus["index"], 2.488);
    double sum = 0, max = 0;
    for (const auto& row : chart["rows"]) {
        sum += row["de2000"]["F0"].get<double>();
        max = std::max(max, row["de2000"]["F0"].get<double>());
    }
    EXPECT_NEAR(versus["de2000_F0"]["mean"].get<double>(), sum / 6, 1e-12);
    EXPECT_EQ(versus["de2000_F0"]["max"].get<double>(), max);
    EXPECT_EQ(chart["stack"]["film"]["material"], "TiO2");
    EXPECT_EQ(chart["description"], "titanium under a TiO2 (Siefke) film of 0–100 nm");
}

TEST_F(CliLayers, ChartFormatsHaveARowPerThickness) {
    const std::string args = "table Ti --film TiO2 --thickness 0:300:10nm --versus 2.488 --format ";
    const Result md = run(args + "md");
    ASSERT_EQ(md.exit_code, 0) << md.err;
    EXPECT_EQ(std::count(md.out.begin(), md.out.end(), '\n'), 2 + 2 + 31 + 2);
    EXPECT_TRUE(Contains(md.out, "ΔE00 against n = 2.488: F0 mean "));
    const Result csv = run(args + "csv");
    ASSERT_EQ(csv.exit_code, 0) << csv.err;
    EXPECT_EQ(std::count(csv.out.begin(), csv.out.end(), '\n'), 32);
    EXPECT_TRUE(Contains(csv.out, "\n300,"));
    const Result html = run(args + "html -o '" + path("chart.html").string() + "'");
    ASSERT_EQ(html.exit_code, 0) << html.err;
    std::ifstream in(path("chart.html"));
    const std::string page((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
    std::size_t rows = 0;
    for (std::size_t at = page.find("<tr><td>"); at != std::string::npos; at = page.find("<tr><td>", at + 1)) ++rows;
    EXPECT_EQ(rows, 31u);
    // A coat over the film, one thickness.
    const Result coated = run("table Fe --film Fe3O4 --coat 1.5 --thickness 60nm --format json");
    ASSERT_EQ(coated.exit_code, 0) << coated.err;
    const auto same = nlohmann::json::parse(run("show Fe --film Fe3O4:60nm --coat 1.5 --json").out);
    EXPECT_LT(max_difference(nlohmann::json::parse(coated.out)["rows"][0]["F0"]["linear"], same["F0"]), 1e-12);
}

TEST_F(CliLayers, BadChartInputIsOneLineAndWritesNothing) {
    const fs::path out = path("chart.json");
    struct Bad {
        std::string args, message;
        int code;
    };
    for (const Bad& bad : {
             Bad{"--film TiO2 --thickness=-5:300:10nm", "--thickness -5:300:10nm: thickness -5 nm is negative", 3},
             Bad{"--film TiO2 --thickness 0:nan:10nm", "thickness nan is not a finite number", 3},
             Bad{"--film TiO2 --thickness 0:inf:10nm", "is not a finite number", 3},
             Bad{"--film TiO2 --thickness 0:300:0nm", "step 0 nm is not a positive finite number", 3},
             Bad{"--film TiO2 --thickness 0:300:-10nm", "step -10 nm is not a positive finite number", 3},
             Bad{"--film TiO2 --thickness 0:2500:10nm", "thickness 2500 nm is beyond 2 µm", 3},
             Bad{"--film TiO2 --thickness 3um", "thickness 3000 nm is beyond 2 µm", 3},
             Bad{"--film TiO2 --thickness 300:0:10nm", "LAST 0 nm is below FIRST 300 nm", 3},
             Bad{"--film TiO2 --thickness 0:2000:0.5nm", "at most 2001", 3},
             Bad{"--film TiO2 --thickness 0:300:10nm --versus nan", "--versus nan: index nan is not a finite", 3},
             Bad{"--film TiO2 --thickness 0:300:10nm --versus -2", "is not a finite number in (0, 1e6]", 3},
             Bad{"--film unobtainium --thickness 0:300:10nm", "unknown film or coat material 'unobtainium'", 2},
             Bad{"--film TiO2 --thickness 0:300:10", "give FIRST:LAST:STEP with a unit", 2},
             Bad{"--film TiO2:80nm --thickness 0:300:10nm", "the thicknesses come from --thickness", 2},
             Bad{"--thickness 0:300:10nm", "--thickness charts a film: give --film", 2},
             Bad{"--film TiO2 --versus 2.488", "--versus compares the oxide chart's film: give --thickness", 2},
         }) {
        const Result r = run("table Ti " + bad.args + " --format json -o '" + out.string() + "'");
        expect_one_line_error(r, bad.code, bad.message);
        EXPECT_FALSE(fs::exists(out)) << bad.args;
    }
    expect_one_line_error(run("table Ti,Au --film TiO2 --thickness 0:300:10nm"), 2, "give one metal");
    expect_one_line_error(run("table anodized-ti-80nm --film TiO2 --thickness 0:300:10nm"), 2,
                          "named finish with layers of its own");
}

}  // namespace test_cli_layers
