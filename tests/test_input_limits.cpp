// Hostile input files (issue 13, items 2, 7, 8): bad data is an InputError naming the file and line, never an
// internal error or a crash; special files and oversized files are refused before they are read.
#include <gtest/gtest.h>

#include "test_support.hpp"

#include <sys/stat.h>
#include <unistd.h>

#include <filesystem>
#include <string>

#include "libfit/base/errors.hpp"
#include "libfit/base/input_file.hpp"
#include "libfit/io/catalog.hpp"
#include "libfit/io/csv.hpp"
#include "libfit/io/refractiveindex.hpp"

namespace metalfit {
namespace test_input_limits {

using namespace metalfit::test;
namespace fs = std::filesystem;

// The message of the InputError that loading `file` throws ("" when it loads).
std::string error_of(const fs::path& file) {
    try {
        load_nk_file(file);
    } catch (const InputError& e) {
        return e.what();
    }
    return "";
}

TEST(InputLimits, ZeroIndexRowsAreBadInputNamingTheLine) {
    TempDir tmp;
    EXPECT_EQ(error_of(tmp.write("z.csv", "wavelength_nm,n,k\n400,0.2,3\n500,0,0\n600,0,0\n700,0.3,4\n")),
              (tmp.path() / "z.csv").string() + ":3: n = k = 0: not a material (the Fresnel reflectance is undefined)");
    const std::string yml = error_of(
        tmp.write("z.yml", "DATA:\n  - type: tabulated nk\n    data: |\n        0.4 0.2 3\n        0.5 0 0\n"));
    EXPECT_TRUE(yml.starts_with((tmp.path() / "z.yml").string() + ":5: ")) << yml;
    EXPECT_TRUE(Contains(yml, "n = k = 0")) << yml;
    // tabulated n with no k data: k = 0 is assumed, so n = 0 is n = k = 0
    const std::string n_only =
        error_of(tmp.write("n.yml", "DATA:\n  - type: tabulated n\n    data: |\n        0.4 0.2\n        0.5 0\n"));
    EXPECT_TRUE(n_only.starts_with((tmp.path() / "n.yml").string() + ":5: ")) << n_only;
    // n = 0 with k > 0 is a valid (if unusual) material
    EXPECT_EQ(error_of(tmp.write("ok.csv", "wavelength_nm,n,k\n400,0,3\n700,0.3,4\n")), "");
}

TEST(InputLimits, AWavelengthOverflowingInNanometresIsBadInput) {
    TempDir tmp;
    const std::string csv = error_of(tmp.write("o.csv", "wavelength_um,n,k\n1e306,0.2,3\n2e306,0.2,3\n"));
    EXPECT_EQ(csv, (tmp.path() / "o.csv").string() +
                       ":2: wavelength 1e306 (column 'wavelength_um') is out of range after unit conversion to nm");
    const std::string yml =
        error_of(tmp.write("o.yml", "DATA:\n  - type: tabulated nk\n    data: |\n        1e307 0.2 3\n"));
    EXPECT_TRUE(yml.starts_with((tmp.path() / "o.yml").string() + ":4: ")) << yml;
}

TEST(InputLimits, ANonUtf8ByteInYamlNamesTheLine) {
    TempDir tmp;
    const std::string e = error_of(
        tmp.write("u.yml", "REFERENCES: \"caf\xe9\"\nDATA:\n  - type: tabulated nk\n    data: |\n        0.4 0.2 3\n"));
    EXPECT_EQ(e, (tmp.path() / "u.yml").string() + ":1: byte 0xE9 is not UTF-8 (a YAML file is UTF-8 text)");
    // Valid UTF-8 (µ, ε) passes.
    EXPECT_EQ(
        error_of(tmp.write(
            "v.yml",
            "REFERENCES: \"\xc2\xb5m, \xce\xb5\"\nDATA:\n  - type: tabulated nk\n    data: |\n        0.4 0.2 3\n        0.5 0.2 3\n")),
        "");
}

TEST(InputLimits, SpecialFilesAreRefusedBeforeReading) {
    TempDir tmp;
    const fs::path fifo = tmp.path() / "f.csv";
    ASSERT_EQ(::mkfifo(fifo.c_str(), 0600), 0);
    EXPECT_EQ(error_of(fifo), fifo.string() + ": cannot read a FIFO: metalfit reads regular files only");  // no hang
    const fs::path zero = tmp.path() / "z.csv";
    fs::create_symlink("/dev/zero", zero);
    EXPECT_EQ(error_of(zero), zero.string() + ": cannot read a character device: metalfit reads regular files only");
    fs::create_directory(tmp.path() / "d.yml");
    EXPECT_TRUE(Contains(error_of(tmp.path() / "d.yml"), "a directory")) << error_of(tmp.path() / "d.yml");
}

TEST(InputLimits, OversizedFilesAndTablesAreRefused) {
    TempDir tmp;
    const fs::path big = tmp.path() / "big.csv";
    {
        std::ofstream out(big);
        out << "wavelength_nm,n,k\n";
    }
    fs::resize_file(big, kMaxInputFileBytes + 1);  // sparse: costs no disk
    EXPECT_TRUE(Contains(error_of(big), "the limit is 16 MiB")) << error_of(big);
    std::string rows = "wavelength_nm,n,k\n";
    for (std::size_t i = 0; i <= kMaxTableRows; ++i) rows += std::to_string(300 + i) + ",1,2\n";
    const std::string many = error_of(tmp.write("many.csv", rows));
    EXPECT_TRUE(Contains(many, ":" + std::to_string(kMaxTableRows + 2) + ": more than 100000 data rows")) << many;
}

}  // namespace test_input_limits
}  // namespace metalfit

namespace metalfit {
namespace test_input_limits {

// Found by fuzz/fuzz_catalog: a number beyond double range was nlohmann's out_of_range, an "internal error".
TEST(InputLimits, ACatalogNumberBeyondDoubleRangeIsBadInput) {
    TempDir tmp;
    tmp.write("catalog.json", "{\"materials\": [], \"x\": 5555555555555555e554555655}");
    try {
        Catalog::load(tmp.path());
        FAIL() << "expected InputError";
    } catch (const InputError& e) {
        EXPECT_TRUE(std::string(e.what()).starts_with((tmp.path() / "catalog.json").string() + ": invalid JSON"))
            << e.what();
    }
}

// Issue 30 (F6): n and k are imported within n, k <= 1e6 and |n + ik| >= 1e-6 (docs/data.md), where the double
// Fresnel is exact (FresnelReal.ExactInsideTheImportRange); beyond, a refusal naming the line, not NaN reflectances.
TEST(InputLimits, IndicesOutsideTheExactFresnelRangeAreRefusedNamingTheLine) {
    TempDir tmp;
    EXPECT_EQ(error_of(tmp.write("edge.csv", "wavelength_nm,n,k\n350,1e6,1e6\n900,1e-6,0\n")), "");
    EXPECT_EQ(error_of(tmp.write("big.csv", "wavelength_nm,n,k\n350,0.2,3\n900,1e78,6\n")),
              (tmp.path() / "big.csv").string() +
                  ":3: refractive index n = 1e78 is above 1e6 (the largest n or k metalfit "
                  "accepts: beyond it the Fresnel reflectance in double precision is not exact)");
    EXPECT_TRUE(Contains(
        error_of(tmp.write(
            "bigk.yml", "DATA:\n  - type: tabulated nk\n    data: |\n        0.4 0.2 3\n        0.5 0.2 1.000001e6\n")),
        "bigk.yml:5: DATA[0].data: extinction coefficient k = 1.000001e6 is above 1e6"));
    EXPECT_TRUE(Contains(
        error_of(tmp.write("tiny.yml", "DATA:\n  - type: tabulated nk\n    data: |\n        0.4 4.9e-324 1e-300\n")),
        "tiny.yml:4: DATA[0].data: |n + ik| is below 1e-6 (n = 4.94e-324, k = 1e-300)"));
    // tabulated n without k: k = 0, so a tiny n is a tiny |n + ik| (as n = 0 is n = k = 0)
    EXPECT_TRUE(Contains(error_of(tmp.write("n.csv", "wavelength_nm,n\n350,1.5\n900,1e-9\n")),
                         "n.csv:3: |n + ik| is below 1e-6"));
    // ε near the double maximum: (|ε| + ε₁)/2 overflowed to inf before (an internal error); now refused by |ε|
    EXPECT_TRUE(Contains(
        error_of(tmp.write("eps.dat", "energy (eV) e1 e2\n3.4 1.7e308 1.7e308\n1.3 -10 1\n")),
        "eps.dat:2: \xce\xb5\xe2\x82\x81 = 1.7e308, \xce\xb5\xe2\x82\x82 = 1.7e308: n or k would be above 1e6"));
    EXPECT_TRUE(Contains(error_of(tmp.write("eps2.dat", "energy (eV) e1 e2\n3.4 -1.5e12 1\n1.3 -10 1\n")),
                         "eps2.dat:2: extinction coefficient k = 1.22474e+06 (from \xce\xb5) is above 1e6"));
    // a formula whose n overflows, or has n² < 0, inside its range
    EXPECT_TRUE(Contains(
        error_of(tmp.write(
            "f.yml", "DATA:\n  - type: formula 1\n    wavelength_range: 0.3 2.5\n    coefficients: 0 1e308 0.1\n")),
        "f.yml:4: DATA[0].coefficients: "));
    EXPECT_TRUE(Contains(
        error_of(tmp.write("g.yml",
                           "DATA:\n  - type: formula 2\n    wavelength_range: 0.3 2.5\n    coefficients: -5 1 0.01\n")),
        "nan at 0.3 \xc2\xb5m (n\xc2\xb2 < 0, a pole or an overflow)"));
}

// Issue 30 (F5): overlong forms, surrogates and code points above U+10FFFF passed the YAML check and reached the
// JSON records (an internal error there); a CSV's column names did too; a file name that is not UTF-8 likewise.
TEST(InputLimits, IllFormedUtf8InAnyImportedTextNamesTheFileAndLine) {
    TempDir tmp;
    const std::string rows = "DATA:\n  - type: tabulated nk\n    data: |\n        0.35 0.2 3\n        0.9 0.2 6\n";
    EXPECT_EQ(error_of(tmp.write("o.yml", "REFERENCES: \"a\xc0\xaf"
                                          "b\"\n" +
                                              rows)),
              (tmp.path() / "o.yml").string() + ":1: overlong encoding C0 AF of U+002F (a YAML file is UTF-8 text)");
    EXPECT_EQ(error_of(tmp.write("s.yml", rows + "COMMENTS: \"\xed\xa0\x80\"\n")),
              (tmp.path() / "s.yml").string() +
                  ":6: UTF-16 surrogate U+D800 (ED A0 80) in UTF-8 (a YAML file is UTF-8 text)");
    EXPECT_EQ(error_of(tmp.write("a.yml", "COMMENTS: \"\xf4\x90\x80\x80\"\n" + rows)),
              (tmp.path() / "a.yml").string() +
                  ":1: code point U+110000 (F4 90 80 80) above U+10FFFF (a YAML file is UTF-8 text)");
    EXPECT_EQ(error_of(tmp.write("c.csv", "wavelength_nm,n,k,MS\xff"
                                          "E\n350,0.2,3,1\n900,0.2,6,1\n")),
              (tmp.path() / "c.csv").string() + ":1: byte 0xFF is not UTF-8 (a table file is UTF-8 text)");
    const fs::path named = tmp.write("caf\xe9.csv", "wavelength_nm,n,k\n350,0.2,3\n900,0.2,6\n");
    EXPECT_EQ(error_of(named),
              (tmp.path()).string() +
                  "/caf\\xE9.csv: the file name is not UTF-8 (byte 0xE9 is not UTF-8); rename the file");
    // a database folder ($METALFIT_DATA) whose path is not UTF-8: the catalog's paths would reach the records
    fs::create_directories(tmp.path() / "d\xff");
    std::filesystem::copy_file(kData / "catalog.json", tmp.path() / "d\xff" / "catalog.json");
    try {
        Catalog::load(tmp.path() / "d\xff");
        FAIL() << "expected InputError";
    } catch (const InputError& e) {
        EXPECT_EQ(std::string(e.what()), tmp.path().string() +
                                             "/d\\xFF/catalog.json: the path of the database is not UTF-8 "
                                             "(byte 0xFF is not UTF-8); rename the folder");
    }
}

// Issue 30 (F19): Å typed as U+00C5 was refused by a message that listed it ("expected nm, um, µm or Å"); both Å code
// points (U+00C5, U+212B), å and "A" are ångström.
TEST(InputLimits, BothAngstromCodePointsAreAngstrom) {
    TempDir tmp;
    for (const char* unit : {"\xc3\x85", "\xe2\x84\xab", "\xc3\xa5", "A", "angstrom"}) {
        const fs::path file =
            tmp.write("a.csv", std::string("wavelength (") + unit + "),n,k\n3500,0.2,3\n9000,0.2,6\n");
        const Material m = load_nk_file(file);
        EXPECT_DOUBLE_EQ(tabulated(m.index.n).wavelengths().front(), 350.0) << unit;
        const fs::path underscore =
            tmp.write("b.csv", std::string("wavelength_") + unit + ",n,k\n3500,0.2,3\n9000,0.2,6\n");
        EXPECT_DOUBLE_EQ(tabulated(load_nk_file(underscore).index.n).wavelengths().back(), 900.0) << unit;
    }
}

}  // namespace test_input_limits
}  // namespace metalfit
