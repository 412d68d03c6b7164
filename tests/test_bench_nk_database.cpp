// The metal nk files of a refractiveindex.info database folder (bench/nk_database) and `metalfit bench
// --scaling-database`: which files are fitted, which are skipped and why; times never asserted.
#include <gtest/gtest.h>

#include <string>

#include <nlohmann/json.hpp>

#include "metalfit_bench/nk_database.hpp"
#include "test_support.hpp"

namespace test_bench_nk_database {

namespace fs = std::filesystem;
using metalfit::test::kData;
using metalfit::test::kMetalfitExe;
using nlohmann::json;

// A refractiveindex.info page of tabulated n, k rows ("λ_µm n k").
std::string nk_page(const std::string& rows) {
    return "REFERENCES: test\nDATA:\n  - type: tabulated nk\n    data: |\n" + rows;
}

// Writes `text` at `relative` under `dir`, making its folders.
void put(const metalfit::test::TempDir& dir, const std::string& relative, const std::string& text) {
    fs::create_directories((dir.path() / relative).parent_path());
    dir.write(relative, text);
}

// A database folder in the refractiveindex.info layout with one file of each kind: two metals (one of them at the
// threshold), a non-metal, a metal table that stops short of 830 nm, a broken page, a page under n2/, a text file.
fs::path make_database(const metalfit::test::TempDir& dir) {
    const fs::path db = dir.path() / "database" / "data";
    fs::create_directories(db / "main" / "Au" / "nk");
    fs::copy_file(kData / "nk" / "Au" / "Johnson.yml", db / "main" / "Au" / "nk" / "Johnson.yml");
    // k = 1 everywhere: the median is exactly the threshold (a metal); k = 0.99: not.
    put(dir, "database/data/main/X/nk/at-threshold.yml", nk_page("        0.3 2.0 1.0\n        0.9 2.0 1.0\n"));
    put(dir, "database/data/main/Y/nk/below.yml", nk_page("        0.3 2.0 0.99\n        0.9 2.0 0.99\n"));
    put(dir, "database/data/main/Z/nk/short.yml", nk_page("        0.3 0.5 3.0\n        0.8 0.5 3.0\n"));
    put(dir, "database/data/main/W/nk/broken.yml", "DATA: [unclosed\n");
    put(dir, "database/data/main/V/n2/Kerr.yml", nk_page("        0.3 2.0 3.0\n        0.9 2.0 3.0\n"));
    put(dir, "database/README.md", "not data\n");
    return dir.path() / "database";
}

TEST(BenchNkDatabase, ScanKeepsTheMetalsAndCountsTheRestByReason) {
    const metalfit::test::TempDir dir;
    const fs::path db = make_database(dir);
    const metalfit::bench::NkDatabaseScan scan = metalfit::bench::scan_nk_database(db);
    EXPECT_EQ(scan.files, 7u);
    ASSERT_EQ(scan.metal_files.size(), 2u);
    EXPECT_EQ(scan.metal_files[0], db / "data" / "main" / "Au" / "nk" / "Johnson.yml");
    EXPECT_EQ(scan.metal_files[1], db / "data" / "main" / "X" / "nk" / "at-threshold.yml");
    EXPECT_EQ(scan.not_nk, 2u);  // README.md, n2/Kerr.yml
    EXPECT_EQ(scan.unreadable, 1u);
    EXPECT_EQ(scan.outside_visible, 1u);
    EXPECT_EQ(scan.not_metal, 1u);
    EXPECT_EQ(scan.files,
              scan.metal_files.size() + scan.not_nk + scan.unreadable + scan.outside_visible + scan.not_metal);
}

// Every file of the repository's own database folder is a metal that covers the visible range (docs/data.md).
TEST(BenchNkDatabase, EveryCatalogTableIsAMetal) {
    const metalfit::bench::NkDatabaseScan scan = metalfit::bench::scan_nk_database(kData / "nk");
    EXPECT_EQ(scan.unreadable + scan.outside_visible + scan.not_metal, 0u);
    EXPECT_EQ(scan.metal_files.size() + scan.not_nk, scan.files);
    EXPECT_GE(scan.metal_files.size(), metalfit::test::catalog_material_count());
}

TEST(BenchNkDatabase, ScalingDatabaseFitsEveryMetalFileOnEachThreadCount) {
    const metalfit::test::TempDir dir;
    const fs::path db = make_database(dir);
    const auto r = metalfit::test::run_command(kMetalfitExe,
                                               "bench --scaling-database '" + db.string() +
                                                   "' --scaling-threads 1,2 --scaling-models schlick,f82-tint --json",
                                               dir.path());
    ASSERT_EQ(r.exit_code, 0) << r.err;
    const json j = json::parse(r.out);
    const json& cells = j.at("cells");
    ASSERT_EQ(cells.size(), 2u);  // no synthetic cells without --scaling
    for (std::size_t i = 0; i < cells.size(); ++i) {
        const json& c = cells[i];
        EXPECT_EQ(c.at("source"), "database");
        EXPECT_EQ(c.at("threads"), static_cast<int>(i + 1));
        EXPECT_EQ(c.at("materials"), 2);
        EXPECT_EQ(c.at("fits"), 4);  // 2 files × 2 models
        EXPECT_GT(c.at("peak_mib").get<double>(), 0.0);
        const json& d = c.at("database");
        EXPECT_EQ(d.at("files"), 7);
        EXPECT_EQ(d.at("fitted"), 2);
        EXPECT_EQ(d.at("skipped"), json({{"not_nk", 2}, {"unreadable", 1}, {"outside_visible", 1}, {"not_metal", 1}}));
    }
    // With --scaling, the synthetic cells come first.
    const auto both = metalfit::test::run_command(kMetalfitExe,
                                                  "bench --scaling --scaling-sizes 1 --scaling-threads 1 "
                                                  "--scaling-models schlick --scaling-database '" +
                                                      db.string() + "'",
                                                  dir.path());
    ASSERT_EQ(both.exit_code, 0) << both.err;
    EXPECT_NE(both.out.find("2 fitted; skipped 2 not nk, 1 unreadable, 1 not covering 360-830 nm, 1 not metal"),
              std::string::npos)
        << both.out;
}

TEST(BenchNkDatabase, AFolderThatIsNotOneIsAUsageError) {
    const metalfit::test::TempDir dir;
    const auto r = metalfit::test::run_command(
        kMetalfitExe, "bench --scaling-database '" + (dir.path() / "nonesuch").string() + "'", dir.path());
    EXPECT_EQ(r.exit_code, 2);
    EXPECT_NE(r.err.find("nonesuch is not a folder"), std::string::npos) << r.err;
    EXPECT_EQ(r.out, "");
}

}  // namespace test_bench_nk_database
