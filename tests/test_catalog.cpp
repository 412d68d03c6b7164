// The built-in catalog: lookup by id, name and alias, sources, load_material, path detection.
#include <gtest/gtest.h>

#include "test_support.hpp"

#include <unistd.h>

#include <filesystem>
#include <fstream>
#include <string>

#include "libfit/base/errors.hpp"
#include "libfit/io/catalog.hpp"
#include "libfit/io/csv.hpp"

namespace metalfit {
namespace test_catalog {

using namespace metalfit::test;

namespace fs = std::filesystem;

// Changes the working directory for the lifetime of the object.
class ScopedCwd {
public:
    explicit ScopedCwd(const fs::path& dir) : previous_(fs::current_path()) { fs::current_path(dir); }
    ~ScopedCwd() {
        std::error_code ec;
        fs::current_path(previous_, ec);
    }
    ScopedCwd(const ScopedCwd&) = delete;
    ScopedCwd& operator=(const ScopedCwd&) = delete;

private:
    fs::path previous_;
};

class CatalogTest : public ::testing::Test {
protected:
    static void SetUpTestSuite() { catalog_ = new Catalog(Catalog::load(kData)); }
    static void TearDownTestSuite() {
        delete catalog_;
        catalog_ = nullptr;
    }
    static const Catalog& catalog() { return *catalog_; }

private:
    static Catalog* catalog_;
};
Catalog* CatalogTest::catalog_ = nullptr;

TEST_F(CatalogTest, LoadsAllMaterials) {
    EXPECT_EQ(catalog().entries().size(), catalog_material_count());
    EXPECT_GE(catalog().entries().size(), 39u);  // the shipped database: no material lost
    EXPECT_EQ(catalog().data_dir(), kData);
    for (const auto& e : catalog().entries()) {
        SCOPED_TRACE(e.id);
        EXPECT_FALSE(e.id.empty());
        EXPECT_FALSE(e.name.empty());
        EXPECT_FALSE(e.primary.source.empty());
        EXPECT_TRUE(e.primary.file.is_absolute() || kData.is_relative()) << e.primary.file;
        EXPECT_TRUE(fs::is_regular_file(e.primary.file)) << e.primary.file;
        for (const auto& a : e.alternates) EXPECT_TRUE(fs::is_regular_file(a.file)) << a.file;
    }
}

TEST_F(CatalogTest, FindIsCaseInsensitiveOnIdNameAndAlias) {
    const CatalogEntry* gold = catalog().find("GOLD");
    ASSERT_NE(gold, nullptr);
    EXPECT_EQ(gold->id, "Au");
    EXPECT_EQ(gold->name, "gold");
    EXPECT_EQ(catalog().find("au"), gold);
    EXPECT_EQ(catalog().find("Au"), gold);
    EXPECT_EQ(catalog().find("gOlD"), gold);
    const CatalogEntry* brass = catalog().find("brass");
    ASSERT_NE(brass, nullptr);
    EXPECT_EQ(brass->id, "Cu-Zn");
    EXPECT_EQ(catalog().find("BRASS"), brass);
    EXPECT_EQ(catalog().find("cu70zn30"), brass);    // alias
    ASSERT_NE(catalog().find("Aluminum"), nullptr);  // alias spelling
    EXPECT_EQ(catalog().find("Aluminum")->id, "Al");
    ASSERT_NE(catalog().find("STAINLESS STEEL"), nullptr);
    EXPECT_EQ(catalog().find("STAINLESS STEEL")->id, "stainless-steel");
    EXPECT_EQ(catalog().find("unobtainium"), nullptr);
    EXPECT_EQ(catalog().find(""), nullptr);
    EXPECT_EQ(catalog().find("gol"), nullptr);  // no prefix matching
}

TEST_F(CatalogTest, FindSource) {
    const CatalogEntry* gold = catalog().find("Au");
    ASSERT_NE(gold, nullptr);
    EXPECT_EQ(&gold->find_source(""), &gold->primary);
    EXPECT_EQ(gold->find_source("").source, "Johnson");
    EXPECT_EQ(&gold->find_source("johnson"), &gold->primary);
    const CatalogSource& mcpeak = gold->find_source("mcpeak");
    EXPECT_EQ(mcpeak.source, "McPeak");
    EXPECT_NE(&mcpeak, &gold->primary);
    EXPECT_EQ(mcpeak.file.filename(), "McPeak.yml");
    try {
        (void)gold->find_source("Palik");
        FAIL() << "unknown source must throw";
    } catch (const UsageError& e) {
        const std::string what = e.what();
        EXPECT_TRUE(Contains(what, "Palik"));
        for (const char* s : {"Johnson", "McPeak", "Babar", "Rakic-LD", "Olmon-ev"}) EXPECT_TRUE(Contains(what, s));
    }
}

TEST_F(CatalogTest, LoadMaterialByName) {
    const Material m = load_material(catalog(), "gold");
    EXPECT_EQ(m.id, "Au");
    EXPECT_EQ(m.name, "gold");
    EXPECT_EQ(m.source, "Johnson");
    EXPECT_EQ(m.provenance.file, catalog().find("Au")->primary.file);
    EXPECT_TRUE(Contains(m.provenance.references, "Johnson"));
    EXPECT_EQ(m.provenance.sha256.size(), 64u);
    EXPECT_TRUE(m.index.range().covers(kVisibleRange));

    const Material alt = load_material(catalog(), "AU", "mcpeak");
    EXPECT_EQ(alt.id, "Au");
    EXPECT_EQ(alt.source, "McPeak");
    EXPECT_NE(alt.provenance.sha256, m.provenance.sha256);
    EXPECT_NE(alt.index(550.0), m.index(550.0));

    const Material brass = load_material(catalog(), "brass");
    EXPECT_EQ(brass.id, "Cu-Zn");
    EXPECT_EQ(brass.name, "brass");
}

TEST_F(CatalogTest, LoadMaterialUnknownNameOrSourceIsUsageError) {
    try {
        (void)load_material(catalog(), "unobtainium");
        FAIL();
    } catch (const UsageError& e) {
        EXPECT_TRUE(Contains(e.what(), "unobtainium"));
    }
    EXPECT_THROW((void)load_material(catalog(), "gold", "Palik"), UsageError);
}

TEST_F(CatalogTest, LoadMaterialFromAFixturePath) {
    const fs::path file = kFixtures / "valid-unsorted-duplicates.yml";
    const Material m = load_material(catalog(), file.string());
    EXPECT_EQ(m.id, "valid-unsorted-duplicates");
    EXPECT_EQ(m.provenance.file, file);
    ASSERT_NE(m.index.n.tabulated(), nullptr);
    EXPECT_EQ(m.index.n.tabulated()->size(), 23u);
    const Material csv = load_material(catalog(), (kFixtures / "valid-nk.csv").string());
    EXPECT_EQ(csv.provenance.format, "CSV");
    // A bad file is an input error, not a usage error.
    EXPECT_THROW((void)load_material(catalog(), (kFixtures / "bad-row.csv").string()), InputError);
    // A source only applies to catalog materials.
    EXPECT_THROW((void)load_material(catalog(), file.string(), "Johnson"), UsageError);
}

TEST(CatalogPaths, LooksLikePath) {
    EXPECT_FALSE(looks_like_path("gold"));
    EXPECT_FALSE(looks_like_path("Cu-Zn"));
    EXPECT_FALSE(looks_like_path("stainless steel"));
    EXPECT_TRUE(looks_like_path("au.yml"));
    EXPECT_TRUE(looks_like_path("au.YAML"));
    EXPECT_TRUE(looks_like_path("table.CSV"));
    EXPECT_TRUE(looks_like_path("dir/gold"));
    EXPECT_TRUE(looks_like_path("./gold"));
    EXPECT_TRUE(looks_like_path("/abs/path/file.txt"));
    EXPECT_TRUE(looks_like_path("gold.txt"));  // instrument tables: .txt, .tsv, .dat
    EXPECT_TRUE(looks_like_path("gold.tsv"));
    EXPECT_TRUE(looks_like_path("gold.DAT"));
    EXPECT_FALSE(looks_like_path("gold.xlsx"));  // not existing, no separator, other extension
}

TEST_F(CatalogTest, AFileInTheCurrentFolderNeverShadowsACatalogName) {
    TempDir dir;
    dir.write("gold", "not a catalog name here\n");
    dir.write("mytable", "wavelength_nm,n,k\n500,0.9,1.9\n600,0.2,3.0\n");
    ScopedCwd cwd(dir.path());
    EXPECT_FALSE(looks_like_path("gold"));
    EXPECT_TRUE(looks_like_path("./gold"));
    // "gold" is the catalog's gold although a file of that name is here; "./gold" is the file (which is no table).
    EXPECT_EQ(load_material(catalog(), "gold").id, "Au");
    EXPECT_THROW((void)load_material(catalog(), "./gold"), InputError);
    // A bare name that is no catalog material but a file here is refused, and the message says why.
    try {
        (void)load_material(catalog(), "mytable");
        ADD_FAILURE() << "a bare file name was taken as a path";
    } catch (const UsageError& e) {
        EXPECT_NE(std::string(e.what()).find("a file of that name is here, but files are read by their extension"),
                  std::string::npos)
            << e.what();
    }
}

// The coverage written into the catalog (scripts/catalog-coverage.py; what `metalfit list` prints without parsing
// the tables) is what the tables give, for every source.
TEST_F(CatalogTest, CoverageMetadataMatchesEveryTable) {
    std::size_t sources = 0;
    for (const CatalogEntry& e : catalog().entries()) {
        std::vector<const CatalogSource*> all{&e.primary};
        for (const CatalogSource& a : e.alternates) all.push_back(&a);
        for (const CatalogSource* s : all) {
            ASSERT_TRUE(s->coverage) << e.id << " " << s->source << ": no coverage (run scripts/catalog-coverage.py)";
            const Material m = load_nk_file(s->file);
            const WavelengthRange r = m.index.range();
            EXPECT_EQ(s->coverage->range_nm.min_nm, r.min_nm)
                << e.id << " " << s->source << " (run scripts/catalog-coverage.py)";
            EXPECT_EQ(s->coverage->range_nm.max_nm, r.max_nm) << e.id << " " << s->source;
            EXPECT_EQ(s->coverage->points_360_830, m.index.n.tabulated_points_in(kVisibleRange))
                << e.id << " " << s->source;
            ++sources;
        }
    }
    EXPECT_GT(sources, catalog().entries().size()) << "alternates must be checked too";
}

TEST(CatalogErrors, CoverageNeedsBothFieldsAndItsShape) {
    TempDir dir;
    const std::string source = R"("source": "S", "file": "nk/Au/S.yml", "reference": "r", "licence": "CC0-1.0")";
    dir.write("catalog.json", R"({"materials": [{"id": "Au", "name": "gold", "primary": {)" + source +
                                  R"(, "range_nm": [300, 900]}}]})");
    try {
        (void)Catalog::load(dir.path());
        FAIL() << "range_nm without points_360_830 must throw";
    } catch (const InputError& e) {
        EXPECT_TRUE(Contains(e.what(), "materials[0].primary.points_360_830")) << e.what();
    }
    dir.write("catalog.json", R"({"materials": [{"id": "Au", "name": "gold", "primary": {)" + source +
                                  R"(, "range_nm": [900, 300], "points_360_830": 3}}]})");
    try {
        (void)Catalog::load(dir.path());
        FAIL() << "a reversed range must throw";
    } catch (const InputError& e) {
        EXPECT_TRUE(Contains(e.what(), "materials[0].primary.range_nm")) << e.what();
    }
    dir.write("catalog.json", R"({"materials": [{"id": "Au", "name": "gold", "primary": {)" + source +
                                  R"(, "range_nm": [300, 900], "points_360_830": 3}}]})");
    const Catalog c = Catalog::load(dir.path());
    ASSERT_TRUE(c.entries().front().primary.coverage);
    EXPECT_EQ(c.entries().front().primary.coverage->points_360_830, 3u);
}

TEST(CatalogErrors, MalformedCatalogJsonIsInputError) {
    TempDir dir;
    dir.write("catalog.json", "{ \"materials\": [ { \"id\": \"Au\", \n");
    try {
        (void)Catalog::load(dir.path());
        FAIL() << "malformed JSON must throw";
    } catch (const InputError& e) {
        const std::string what = e.what();
        EXPECT_TRUE(Contains(what, "catalog.json"));
        EXPECT_EQ(what.find('\n'), std::string::npos) << what;
        EXPECT_EQ(e.location().file, dir.path() / "catalog.json");
    }
}

TEST(CatalogErrors, MissingFieldIsNamed) {
    TempDir dir;
    dir.write("catalog.json", R"({"materials": [{"id": "Au", "name": "gold"}]})");
    try {
        (void)Catalog::load(dir.path());
        FAIL() << "a material without primary must throw";
    } catch (const InputError& e) {
        EXPECT_TRUE(Contains(e.what(), "catalog.json"));
        EXPECT_TRUE(Contains(e.what(), "materials[0].primary"));
    }
    dir.write("catalog.json", R"({"stuff": []})");
    try {
        (void)Catalog::load(dir.path());
        FAIL();
    } catch (const InputError& e) {
        EXPECT_TRUE(Contains(e.what(), "materials"));
    }
}

TEST(CatalogErrors, MissingCatalogIsInputError) {
    TempDir dir;
    try {
        (void)Catalog::load(dir.path());
        FAIL();
    } catch (const InputError& e) {
        EXPECT_TRUE(Contains(e.what(), "catalog.json"));
    }
}

TEST(CatalogErrors, MinimalCatalogResolvesFilesAgainstItsDirectory) {
    TempDir dir;
    fs::create_directories(dir.path() / "nk");
    fs::copy_file(kFixtures / "valid-nk.csv", dir.path() / "nk/table.csv");
    dir.write("catalog.json", R"({"materials": [{"id": "Xx", "name": "test metal", "aliases": ["tm"],
        "primary": {"source": "Me", "file": "nk/table.csv", "reference": "nobody", "licence": "CC0"}}]})");
    const Catalog c = Catalog::load(dir.path());
    ASSERT_EQ(c.entries().size(), 1u);
    EXPECT_EQ(c.entries()[0].primary.file, dir.path() / "nk/table.csv");
    EXPECT_TRUE(c.entries()[0].alternates.empty());
    const Material m = load_material(c, "TM");
    EXPECT_EQ(m.id, "Xx");
    EXPECT_EQ(m.name, "test metal");
    EXPECT_EQ(m.source, "Me");
    EXPECT_EQ(m.provenance.format, "CSV");
}

}  // namespace test_catalog
}  // namespace metalfit
