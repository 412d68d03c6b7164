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
namespace {

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
    const std::string yml = error_of(tmp.write("z.yml", "DATA:\n  - type: tabulated nk\n    data: |\n        0.4 0.2 3\n        0.5 0 0\n"));
    EXPECT_TRUE(yml.starts_with((tmp.path() / "z.yml").string() + ":5: ")) << yml;
    EXPECT_TRUE(Contains(yml, "n = k = 0")) << yml;
    // tabulated n with no k data: k = 0 is assumed, so n = 0 is n = k = 0
    const std::string n_only = error_of(tmp.write("n.yml", "DATA:\n  - type: tabulated n\n    data: |\n        0.4 0.2\n        0.5 0\n"));
    EXPECT_TRUE(n_only.starts_with((tmp.path() / "n.yml").string() + ":5: ")) << n_only;
    // n = 0 with k > 0 is a valid (if unusual) material
    EXPECT_EQ(error_of(tmp.write("ok.csv", "wavelength_nm,n,k\n400,0,3\n700,0.3,4\n")), "");
}

TEST(InputLimits, AWavelengthOverflowingInNanometresIsBadInput) {
    TempDir tmp;
    const std::string csv = error_of(tmp.write("o.csv", "wavelength_um,n,k\n1e306,0.2,3\n2e306,0.2,3\n"));
    EXPECT_EQ(csv, (tmp.path() / "o.csv").string() +
                       ":2: wavelength 1e306 (column 'wavelength_um') is out of range after unit conversion to nm");
    const std::string yml = error_of(tmp.write("o.yml", "DATA:\n  - type: tabulated nk\n    data: |\n        1e307 0.2 3\n"));
    EXPECT_TRUE(yml.starts_with((tmp.path() / "o.yml").string() + ":4: ")) << yml;
}

TEST(InputLimits, ANonUtf8ByteInYamlNamesTheLine) {
    TempDir tmp;
    const std::string e = error_of(tmp.write("u.yml", "REFERENCES: \"caf\xe9\"\nDATA:\n  - type: tabulated nk\n    data: |\n        0.4 0.2 3\n"));
    EXPECT_EQ(e, (tmp.path() / "u.yml").string() + ":1: byte 0xE9 is not UTF-8 (a YAML file is UTF-8 text)");
    // Valid UTF-8 (µ, ε) passes.
    EXPECT_EQ(error_of(tmp.write("v.yml", "REFERENCES: \"\xc2\xb5m, \xce\xb5\"\nDATA:\n  - type: tabulated nk\n    data: |\n        0.4 0.2 3\n        0.5 0.2 3\n")), "");
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

}  // namespace
}  // namespace metalfit

namespace metalfit {
namespace {

// Found by fuzz/fuzz_catalog: a number beyond double range was nlohmann's out_of_range, an "internal error".
TEST(InputLimits, ACatalogNumberBeyondDoubleRangeIsBadInput) {
    TempDir tmp;
    tmp.write("catalog.json", "{\"materials\": [], \"x\": 5555555555555555e554555655}");
    try {
        Catalog::load(tmp.path());
        FAIL() << "expected InputError";
    } catch (const InputError& e) {
        EXPECT_TRUE(std::string(e.what()).starts_with((tmp.path() / "catalog.json").string() + ": invalid JSON")) << e.what();
    }
}

}  // namespace
}  // namespace metalfit
