// The bad-input sweep (issue 30, goal 4): every importer — refractiveindex.info YAML, CSV and instrument tables, the
// catalog, an OCIO config given with --ocio-config, glpreview's scene JSON — and the command line itself, fed numbers at
// and beyond the double range (1e308, 1e309, -1e309, 4.9e-324, nan, inf) and ill-formed UTF-8 of every class (a bad
// byte, an overlong form, a surrogate, a code point above U+10FFFF, a truncated sequence) at every kind of place (a
// key, a value, a name, a unit, the end of the file), through the real executables. Each run must end with exit code
// 2, 3 or 4 and exactly one line on stderr naming the file (or the command-line value) — never an internal error
// (1), a crash, or a record with null numbers.
#include <gtest/gtest.h>

#include "test_support.hpp"

#include <algorithm>
#include <filesystem>
#include <string>
#include <vector>

#include "libfit/base/errors.hpp"

namespace test_bad_input_sweep {

namespace fs = std::filesystem;
using metalfit::sanitised_message;
using metalfit::test::CommandResult;
using metalfit::test::kData;
using metalfit::test::kMetalfitExe;
using metalfit::test::read_file;
using metalfit::test::TempDir;

const std::vector<std::string> kNumbers = {"1e308", "1e309", "-1e309", "4.9e-324", "nan", "inf"};
const std::vector<std::string> kBadUtf8 = {"\xff",         "\xc0\xaf",         "\xe0\x80\xaf",
                                           "\xed\xa0\x80", "\xf4\x90\x80\x80", "\xe2\x82"};

// "x@y" with every @ replaced by `value`.
std::string fill(std::string text, const std::string& value) {
    for (std::size_t at; (at = text.find('@')) != std::string::npos;) text.replace(at, 1, value);
    return text;
}

// A template, where its @ go, and which of kNumbers it is fed (a value that is valid there is left out, e.g. a
// tiny k beside n = 1).
struct Template {
    std::string label, file_name, text;
    std::vector<std::string> values;
};

class BadInputSweep : public ::testing::Test {
protected:
    // Runs `exe` and checks the contract: exit 2, 3 or 4, stdout empty, stderr one line containing `names`.
    void expect_refused(const fs::path& exe, const std::string& args, const std::string& names,
                        const std::string& label, const std::string& env = "OCIO=") {
        const CommandResult r = metalfit::test::run_command(exe, args, tmp_.path(), env);
        const std::string where = label + ": " + sanitised_message(r.err);
        EXPECT_TRUE(r.exit_code == 2 || r.exit_code == 3 || r.exit_code == 4)
            << where << " (exit " << r.exit_code << ")";
        EXPECT_EQ(std::count(r.err.begin(), r.err.end(), '\n'), 1) << where;
        EXPECT_TRUE(!r.err.empty() && r.err.back() == '\n') << where;
        EXPECT_NE(r.err.find(sanitised_message(names)), std::string::npos) << where << " does not name " << names;
        EXPECT_EQ(r.out, "") << where;
    }

    // Every template with every value it takes, loaded by `metalfit <command> FILE`.
    void sweep_files(const std::vector<Template>& templates, const std::string& command) {
        for (const Template& t : templates)
            for (const std::string& value : t.values) {
                const fs::path file = tmp_.write(t.file_name, fill(t.text, value));
                expect_refused(kMetalfitExe, command + " '" + file.string() + "'", file.string(),
                               t.label + " [" + sanitised_message(value) + "]");
            }
    }

    TempDir tmp_;
};

const std::string kYamlRows = "        0.4 0.2 3\n        0.6 0.3 4\n        0.9 0.2 6\n";

TEST_F(BadInputSweep, RefractiveindexYaml) {
    const std::string head = "DATA:\n  - type: tabulated nk\n    data: |\n";
    std::vector<std::string> no_tiny = kNumbers;
    no_tiny.erase(std::find(no_tiny.begin(), no_tiny.end(), "4.9e-324"));
    std::vector<Template> templates = {
        {"n and k", "s.yml", head + "        0.4 @ @\n        0.6 @ @\n        0.9 @ @\n", kNumbers},
        {"n", "s.yml", head + "        0.4 @ 3\n        0.6 @ 4\n        0.9 @ 6\n", no_tiny},
        {"k", "s.yml", head + "        0.4 0.2 @\n        0.6 0.3 @\n        0.9 0.2 @\n", no_tiny},
        {"wavelength", "s.yml", head + "        @ 0.2 3\n        0.6 0.3 4\n", kNumbers},
        {"tabulated n", "s.yml", "DATA:\n  - type: tabulated n\n    data: |\n        0.3 @\n        0.9 @\n", kNumbers},
        {"formula coefficient", "s.yml",
         "DATA:\n  - type: formula 1\n    wavelength_range: 0.3 2.5\n    coefficients: 0 @ 0.1\n", no_tiny},
        {"formula range", "s.yml",
         "DATA:\n  - type: formula 2\n    wavelength_range: 0.3 @\n    coefficients: 0 1 0.01\n", no_tiny},
    };
    for (const std::string& bad : kBadUtf8) {
        const std::vector<std::string> one{bad};
        templates.push_back({"utf-8 in a key", "s.yml", "REFER@ENCES: x\n" + head + kYamlRows, one});
        templates.push_back({"utf-8 in a value", "s.yml", "REFERENCES: \"caf@\"\n" + head + kYamlRows, one});
        templates.push_back({"utf-8 in a condition", "s.yml", head + kYamlRows + "CONDITIONS:\n  medium: @\n", one});
        templates.push_back(
            {"utf-8 in the type", "s.yml", "DATA:\n  - type: tabulated@ nk\n    data: |\n" + kYamlRows, one});
        templates.push_back({"utf-8 in a row", "s.yml", head + "        0.4 0.2 3\n        0.6 0.3@ 4\n", one});
        templates.push_back({"utf-8 at the end", "s.yml", head + kYamlRows + "# end@", one});
    }
    sweep_files(templates, "show --json");
}

TEST_F(BadInputSweep, CsvAndInstrumentTables) {
    std::vector<std::string> no_tiny = kNumbers;
    no_tiny.erase(std::find(no_tiny.begin(), no_tiny.end(), "4.9e-324"));
    std::vector<Template> templates = {
        {"n and k", "s.csv", "wavelength_nm,n,k\n400,@,@\n600,@,@\n900,@,@\n", kNumbers},
        {"n", "s.csv", "wavelength_nm,n,k\n400,@,3\n600,@,4\n900,@,6\n", no_tiny},
        {"k", "s.csv", "wavelength_nm,n,k\n400,0.2,@\n600,0.3,@\n900,0.2,@\n", no_tiny},
        {"n only", "s.csv", "wavelength_nm,n\n400,@\n900,@\n", kNumbers},
        {"wavelength", "s.csv", "wavelength_nm,n,k\n@,0.2,3\n600,0.3,4\n", kNumbers},
        {"energy", "s.tsv", "energy (eV)\tn\tk\n@\t0.2\t3\n1.5\t0.3\t4\n", kNumbers},
        {"e1 and e2", "s.dat", "energy (eV) e1 e2\n3.4 @ @\n2 @ @\n1.3 @ @\n", kNumbers},
        {"e1", "s.dat", "energy (eV) e1 e2\n3.4 @ 1\n2 @ 2\n1.3 @ 3\n", no_tiny},
        {"e2", "s.txt", "energy (eV);e1;e2\n3,4;-10;@\n2;-20;@\n1,3;-30;@\n", no_tiny},
    };
    for (const std::string& bad : kBadUtf8) {
        const std::vector<std::string> one{bad};
        templates.push_back(
            {"utf-8 in a column name", "s.csv", "wavelength_nm,n,k,MS@E\n400,0.2,3,1\n900,0.2,6,1\n", one});
        templates.push_back({"utf-8 in a unit", "s.tsv", "wavelength (n@m)\tn\tk\n400\t0.2\t3\n900\t0.2\t6\n", one});
        templates.push_back({"utf-8 in a value", "s.csv", "wavelength_nm,n,k\n400,0.2@,3\n900,0.2,6\n", one});
        templates.push_back({"utf-8 in a comment", "s.csv", "# caf@\nwavelength_nm,n,k\n400,0.2,3\n900,0.2,6\n", one});
        templates.push_back({"utf-8 at the end", "s.csv", "wavelength_nm,n,k\n400,0.2,3\n900,0.2,6\n@", one});
    }
    sweep_files(templates, "show --json");
}

// The values of the command line: labels, materials, paths (a file name that is not UTF-8), options.
TEST_F(BadInputSweep, CommandLineValues) {
    const fs::path good = tmp_.write("good.csv", "wavelength_nm,n,k\n350,0.2,3\n900,0.2,6\n");
    for (const std::string& bad : kBadUtf8) {
        const std::string label = "[" + sanitised_message(bad) + "]";
        expect_refused(kMetalfitExe, "show '" + good.string() + "' --name 'a" + bad + "'", "--name", "--name " + label);
        expect_refused(kMetalfitExe, "fit '" + good.string() + "' --model schlick --reference 'r" + bad + "'",
                       "--reference", "--reference " + label);
        const fs::path named = tmp_.write("m" + bad + ".csv", read_file(good));
        expect_refused(kMetalfitExe, "show '" + named.string() + "'", named.string(), "file name " + label);
        expect_refused(kMetalfitExe, "show 'gold" + bad + "'", "gold", "material " + label);
        expect_refused(kMetalfitExe, "show gold --space 'ACES" + bad + "'", "--space", "--space " + label);
        fs::remove(named);
    }
}

// --data-dir with a catalog.json of one material (the data file given by its absolute path).
TEST_F(BadInputSweep, Catalog) {
    const fs::path nk = kData / "nk" / "Au" / "Johnson.yml";
    const std::string ocio = "--ocio-config '" + (kData / "ocio" / "config.ocio").string() + "' ";
    const auto catalog = [&](const std::string& key, const std::string& name, const std::string& range_min) {
        return "{\"materials\": [{\"id\": \"gold\", \"" + key + "\": \"" + name +
               "\", \"primary\": {\"source\": \"Johnson\", \"file\": \"" + nk.string() +
               "\", \"reference\": \"r\", \"licence\": \"CC0\", \"range_nm\": [" + range_min +
               ", 830], \"points_360_830\": 10}}]}\n";
    };
    fs::create_directories(tmp_.path() / "d");
    const fs::path file = tmp_.path() / "d" / "catalog.json";
    const std::string args = "--data-dir '" + (tmp_.path() / "d").string() + "' " + ocio;
    for (const std::string& value : kNumbers) {
        if (value == "4.9e-324") continue;  // a valid range_nm start
        tmp_.write("d/catalog.json", catalog("name", "Gold", value));
        expect_refused(kMetalfitExe, args + "list --json", file.string(), "range_nm [" + value + "]");
    }
    for (const std::string& bad : kBadUtf8) {
        const std::string label = "[" + sanitised_message(bad) + "]";
        tmp_.write("d/catalog.json", catalog("name", "Go" + bad + "ld", "360"));
        expect_refused(kMetalfitExe, args + "list --json", file.string(), "utf-8 in a value " + label);
        tmp_.write("d/catalog.json", catalog("na" + bad + "me", "Gold", "360"));
        expect_refused(kMetalfitExe, args + "show gold --json", file.string(), "utf-8 in a key " + label);
        tmp_.write("d/catalog.json", catalog("name", "Gold", "360") + bad);
        expect_refused(kMetalfitExe, args + "list --json", file.string(), "utf-8 at the end " + label);
    }
}

// An OCIO config given with --ocio-config: numbers in a matrix of a target space, ill-formed UTF-8 in a family, a
// name, a key and at the end (`spaces` reads every name and family).
TEST_F(BadInputSweep, OcioConfig) {
    const std::string config = read_file(kData / "ocio" / "config.ocio");
    const std::string matrix =
        "[0.486570948648216, 0.265667693169093, 0.198217285234362, 0.0, 0.228974564069749, "
        "0.691738521836506, 0.079286914093745, 0.0, -0.0, 0.045113381858903, 1.043944368900976, 0.0, "
        "0.0, 0.0, 0.0, 1.0]";
    ASSERT_NE(config.find(matrix), std::string::npos);
    const auto with = [&](const std::string& from, const std::string& to) {
        std::string text = config;
        const std::size_t at = text.find(from);
        EXPECT_NE(at, std::string::npos) << from;
        return text.replace(at, from.size(), to);
    };
    const fs::path file = tmp_.path() / "c.ocio";
    const std::string args = "--ocio-config '" + file.string() + "' ";
    for (const std::string& value : kNumbers) {
        tmp_.write("c.ocio", with(matrix, fill("[@, 0, 0, 0, 0, @, 0, 0, 0, 0, @, 0, 0, 0, 0, 1]", value)));
        expect_refused(kMetalfitExe, args + "show gold --json --space 'Linear P3-D65'", file.string(),
                       "matrix [" + value + "]");
    }
    for (const std::string& bad : kBadUtf8) {
        const std::string label = "[" + sanitised_message(bad) + "]";
        tmp_.write("c.ocio", with("    family: Utility\n", "    family: Util" + bad + "ity\n"));
        expect_refused(kMetalfitExe, args + "spaces --json", file.string(), "family " + label);
        tmp_.write("c.ocio", with("    name: ACEScg\n", "    name: ACES" + bad + "cg\n"));
        expect_refused(kMetalfitExe, args + "spaces --json", file.string(), "name " + label);
        tmp_.write("c.ocio", with("    family: Utility\n", "    fam" + bad + "ily: Utility\n"));
        expect_refused(kMetalfitExe, args + "spaces --json", file.string(), "key " + label);
        tmp_.write("c.ocio", config + "# " + bad);
        expect_refused(kMetalfitExe, args + "spaces --json", file.string(), "end " + label);
    }
}

// Issue 30 (F4): a colour space whose transforms refer back to it (directly, or through another space) sent OCIO's
// getProcessor into endless recursion: SIGSEGV in `spaces`, and in `show --space` of it or of the XYZ space.
TEST_F(BadInputSweep, OcioColourSpaceThatConvertsToItselfIsAColourConfigurationError) {
    const std::string config = read_file(kData / "ocio" / "config.ocio");
    const std::string p3 = "        - !<MatrixTransform> {matrix: [0.486570948648216";
    ASSERT_NE(config.find(p3), std::string::npos);
    const fs::path file = tmp_.path() / "c.ocio";
    const std::string args = "--ocio-config '" + file.string() + "' ";
    std::string self = config;
    self.insert(self.find(p3),
                "        - !<ColorSpaceTransform> {src: lin_p3d65, dst: ACES2065-1}\n");  // through its alias
    tmp_.write("c.ocio", self);
    for (const char* command : {"spaces --json", "show gold --json --space 'Linear P3-D65'", "show gold --json"}) {
        expect_refused(kMetalfitExe, args + command, file.string(), command);
        const CommandResult r = metalfit::test::run_command(kMetalfitExe, args + command, tmp_.path());
        EXPECT_NE(
            r.err.find("colour space 'Linear P3-D65' converts to itself (Linear P3-D65 \xe2\x86\x92 Linear P3-D65)"),
            std::string::npos)
            << r.err;
    }
    // Two spaces through each other: Linear Rec.2020 from P3 and P3 from Rec.2020 (named by its alias).
    const std::string rec2020 = "        - !<MatrixTransform> {matrix: [0.636958048301291";
    ASSERT_NE(config.find(rec2020), std::string::npos);
    std::string pair = config;
    pair.insert(pair.find(rec2020), "        - !<ColorSpaceTransform> {src: Linear P3-D65, dst: ACES2065-1}\n");
    pair.insert(pair.find(p3), "        - !<ColorSpaceTransform> {src: lin_rec2020, dst: ACES2065-1}\n");
    tmp_.write("c.ocio", pair);
    expect_refused(kMetalfitExe, args + "show gold --json --space 'Linear P3-D65'", file.string(), "two spaces");
    EXPECT_NE(metalfit::test::run_command(kMetalfitExe, args + "spaces", tmp_.path()).err.find("converts to itself"),
              std::string::npos);
}

// glpreview's scene JSON (--explain: parsed and planned, nothing rendered) and its command line.
TEST_F(BadInputSweep, GlpreviewScene) {
    const fs::path glpreview = fs::path(kMetalfitExe).parent_path() / "glpreview";
    if (!fs::exists(glpreview)) GTEST_SKIP() << "glpreview not built";
    const std::string scene =
        "{\"image\": {\"width\": @W, \"height\": 64}, \"camera\": {\"position\": [0, 0.3, 3], \"look_at\": [0, 0.2, 0], "
        "\"fov_y_deg\": @F}, \"environment\": {\"type\": \"room\", \"min\": [-3, 0, -3], \"max\": [3, 3, 3], \"reference_point\": [0, 1.2, 0]}, \"spheres\": [{\"center\": [0, 0.2, 0], \"radius\": @R, "
        "\"material\": \"Au@M\", \"fresnel\": \"reference\", \"reflection\": \"classic\"}]}\n";
    const auto make = [&](const std::string& w, const std::string& f, const std::string& r, const std::string& m) {
        std::string text = scene;
        for (const auto& [key, value] : {std::pair{"@W", w}, {"@F", f}, {"@R", r}, {"@M", m}})
            text.replace(text.find(key), 2, value);
        return text;
    };
    const fs::path file = tmp_.path() / "s.json";
    for (const std::string& value : kNumbers) {
        tmp_.write("s.json", make(value, "40", "0.5", ""));
        expect_refused(glpreview, "--explain '" + file.string() + "'", file.string(), "width [" + value + "]");
        tmp_.write("s.json", make("64", value, "0.5", ""));
        expect_refused(glpreview, "--explain '" + file.string() + "'", file.string(), "fov [" + value + "]");
        if (value == "4.9e-324") continue;  // a tiny sphere is a sphere
        tmp_.write("s.json", make("64", "40", value, ""));
        expect_refused(glpreview, "--explain '" + file.string() + "'", file.string(), "radius [" + value + "]");
    }
    for (const std::string& bad : kBadUtf8) {
        const std::string label = "[" + sanitised_message(bad) + "]";
        tmp_.write("s.json", make("64", "40", "0.5", bad));
        expect_refused(glpreview, "--explain '" + file.string() + "'", file.string(), "material " + label);
        tmp_.write("s.json", make("64", "40", "0.5", "") + bad);
        expect_refused(glpreview, "--explain '" + file.string() + "'", file.string(), "end " + label);
        const fs::path named = tmp_.write("s" + bad + ".json", make("64", "40", "0.5", ""));
        expect_refused(glpreview, "--explain '" + named.string() + "'", named.string(), "scene file name " + label);
        fs::remove(named);
    }
}

}  // namespace test_bad_input_sweep
