// Importer for refractiveindex.info YAML: every fixture in tests/fixtures and every catalog file.
#include <gtest/gtest.h>

#include "test_support.hpp"

#include <unistd.h>

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <string>
#include <vector>

#include "libfit/base/errors.hpp"
#include "libfit/base/file_digest.hpp"
#include "libfit/io/catalog.hpp"
#include "libfit/io/csv.hpp"
#include "libfit/io/refractiveindex.hpp"

namespace metalfit {
namespace test_io_refractiveindex {

using namespace metalfit::test;

namespace fs = std::filesystem;

bool is_lower_hex(const std::string& s) {
    for (char c : s)
        if (!((c >= '0' && c <= '9') || (c >= 'a' && c <= 'f'))) return false;
    return true;
}

// ---------------------------------------------------------------------------------------------
// Valid files

TEST(IoRefractiveIndexTabulatedNk, JohnsonGold) {
    const fs::path file = kData / "nk/Au/Johnson.yml";
    const Material m = load_refractiveindex_yaml(file);
    const Spectrum& n = tabulated(m.index.n);
    const Spectrum& k = tabulated(m.index.k);
    // µm → nm, whole file: 0.1879–1.9370 µm.
    EXPECT_NEAR(n.range().min_nm, 187.9, 1e-9);
    EXPECT_NEAR(n.range().max_nm, 1937.0, 1e-9);
    EXPECT_NEAR(m.index.range().min_nm, 187.9, 1e-9);
    EXPECT_NEAR(m.index.range().max_nm, 1937.0, 1e-9);
    EXPECT_EQ(n.size(), k.size());
    EXPECT_EQ(n.identical_duplicates() + n.conflicting_duplicates(), 0u);
    // Row `0.5486 0.43 2.455`: the file's values exactly, at the tabulated wavelength.
    const std::size_t i = index_of(n, 548.6);
    ASSERT_LT(i, n.size());
    EXPECT_EQ(n.values()[i], 0.43);
    EXPECT_EQ(k.values()[index_of(k, 548.6)], 2.455);
    const double at = n.wavelengths()[i];
    EXPECT_EQ(m.index.n(at, Interpolation::linear, OutOfRange::error), 0.43);
    EXPECT_EQ(m.index.k(at, Interpolation::pchip, OutOfRange::error), 2.455);
    EXPECT_NEAR(m.index(548.6).real(), 0.43, 1e-9);
    EXPECT_NEAR(m.index(548.6).imag(), 2.455, 1e-9);
    // First and last rows: `0.1879 1.28 1.188`, `1.9370 0.92 13.78`.
    EXPECT_EQ(n.values().front(), 1.28);
    EXPECT_EQ(k.values().front(), 1.188);
    EXPECT_EQ(n.values().back(), 0.92);
    EXPECT_EQ(k.values().back(), 13.78);
    // Linear between `0.6168 0.21 3.272` and `0.6595 0.14 3.697` at the midpoint.
    EXPECT_NEAR(m.index((616.8 + 659.5) / 2.0).real(), (0.21 + 0.14) / 2.0, 1e-9);
    EXPECT_NEAR(m.index((616.8 + 659.5) / 2.0).imag(), (3.272 + 3.697) / 2.0, 1e-9);
    // Provenance.
    EXPECT_TRUE(Contains(m.provenance.references, "P. B. Johnson and R. W. Christy."));
    EXPECT_TRUE(Contains(m.provenance.references, "10.1103/PhysRevB.6.4370"));
    EXPECT_TRUE(Contains(m.provenance.comments, "Room temperature"));
    EXPECT_EQ(m.provenance.data_type, "tabulated nk");
    EXPECT_EQ(m.provenance.format, "refractiveindex.info YAML");
    EXPECT_EQ(m.provenance.file, file);
    EXPECT_EQ(m.provenance.sha256.size(), 64u);
    EXPECT_TRUE(is_lower_hex(m.provenance.sha256)) << m.provenance.sha256;
    EXPECT_EQ(m.provenance.sha256, sha256_file(file));
    EXPECT_EQ(load_refractiveindex_yaml(file).provenance.sha256, m.provenance.sha256);
    EXPECT_EQ(m.id, "Johnson");  // file stem for a file loaded directly
    EXPECT_TRUE(m.warnings.empty());
}

TEST(IoRefractiveIndexTabulatedNk, DifferentFilesHaveDifferentDigests) {
    const Material a = load_refractiveindex_yaml(kData / "nk/Au/Johnson.yml");
    const Material b = load_refractiveindex_yaml(kFixtures / "valid-unsorted-duplicates.yml");
    EXPECT_NE(a.provenance.sha256, b.provenance.sha256);
}

TEST(IoRefractiveIndexSeparateBlocks, SiliconGreenNAndKOnDifferentGrids) {
    const fs::path file = kFixtures / "refractiveindex/Si-Green-1995.yml";
    const Material m = load_refractiveindex_yaml(file);
    const Spectrum& n = tabulated(m.index.n);
    const Spectrum& k = tabulated(m.index.k);
    EXPECT_EQ(n.size(), 121u);
    EXPECT_EQ(k.size(), 76u);
    EXPECT_NEAR(n.range().min_nm, 250.0, 1e-9);
    EXPECT_NEAR(n.range().max_nm, 1450.0, 1e-9);
    EXPECT_NEAR(k.range().min_nm, 250.0, 1e-9);
    EXPECT_NEAR(k.range().max_nm, 1000.0, 1e-9);
    // Where both are defined: the overlap.
    EXPECT_NEAR(m.index.range().min_nm, 250.0, 1e-9);
    EXPECT_NEAR(m.index.range().max_nm, 1000.0, 1e-9);
    // Rows `0.26 1.800` (n) and `0.26 4.072` (k); `1.45 3.486` (last n); `1.00 0.001` (last k).
    EXPECT_EQ(n.values()[index_of(n, 260.0)], 1.800);
    EXPECT_EQ(k.values()[index_of(k, 260.0)], 4.072);
    EXPECT_EQ(n.values().back(), 3.486);
    EXPECT_EQ(k.values().back(), 0.001);
    const std::complex<double> eta = m.index(n.wavelengths()[index_of(n, 260.0)]);
    EXPECT_EQ(eta.real(), 1.800);
    EXPECT_EQ(eta.imag(), 4.072);
    // n exists beyond the k data, the complex index does not.
    EXPECT_NO_THROW((void)m.index.n(1200.0, Interpolation::linear, OutOfRange::error));
    EXPECT_THROW((void)m.index(1200.0), SpectrumRangeError);
    EXPECT_EQ(m.provenance.data_type, "tabulated n + tabulated k");
    EXPECT_TRUE(Contains(m.provenance.references, "Green"));
    EXPECT_TRUE(m.warnings.empty());
}

TEST(IoRefractiveIndexFormula, Formula1FusedSilicaMalitson) {
    const fs::path file = kFixtures / "refractiveindex/SiO2-Malitson.yml";
    const Material m = load_refractiveindex_yaml(file);
    EXPECT_EQ(m.index.n.kind(), "formula 1");
    EXPECT_NEAR(m.index.n.range().min_nm, 210.0, 1e-9);
    EXPECT_NEAR(m.index.n.range().max_nm, 6700.0, 1e-9);
    EXPECT_NEAR(m.index(587.5618).real(), 1.458464, 1e-6);
    // No k in the file: k = 0 everywhere, with a warning.
    EXPECT_EQ(m.index.k.kind(), "constant");
    EXPECT_EQ(m.index(587.5618).imag(), 0.0);
    EXPECT_EQ(m.index(5000.0).imag(), 0.0);
    ASSERT_EQ(m.warnings.size(), 1u);
    EXPECT_TRUE(Contains(m.warnings[0], "k = 0"));
    EXPECT_EQ(m.warnings[0].find('\n'), std::string::npos);
    // Formula evaluation outside the formula's range is refused.
    EXPECT_THROW((void)m.index(200.0), SpectrumRangeError);
    // CONDITIONS after DATA kept; COMMENTS and REFERENCES too.
    ASSERT_EQ(m.provenance.conditions.count("temperature"), 1u);
    EXPECT_EQ(m.provenance.conditions.at("temperature"), "293");
    EXPECT_TRUE(Contains(m.provenance.comments, "Fused silica"));
    EXPECT_TRUE(Contains(m.provenance.references, "Malitson"));
    EXPECT_EQ(m.provenance.data_type, "formula 1");
}

TEST(IoRefractiveIndexFormula, Formula2SchottNbk7) {
    const fs::path file = kFixtures / "valid-formula2.yml";
    const Material m = load_refractiveindex_yaml(file);
    EXPECT_EQ(m.index.n.kind(), "formula 2");
    EXPECT_NEAR(m.index.range().min_nm, 300.0, 1e-9);
    EXPECT_NEAR(m.index.range().max_nm, 2500.0, 1e-9);
    const std::vector<std::pair<double, double>> expected{{300.0, 1.552770},    {486.1327, 1.522376},
                                                          {587.5618, 1.516800}, {656.2725, 1.514322},
                                                          {1000.0, 1.507502},   {2500.0, 1.486018}};
    for (const auto& [nm, n] : expected) {
        EXPECT_NEAR(m.index(nm).real(), n, 1e-6) << nm;
        EXPECT_EQ(m.index(nm).imag(), 0.0) << nm;
    }
    ASSERT_EQ(m.provenance.conditions.count("film_thickness"), 1u);
    EXPECT_EQ(m.provenance.conditions.at("film_thickness"), "50e-9");
    ASSERT_EQ(m.provenance.conditions.count("temperature"), 1u);
    EXPECT_EQ(m.provenance.conditions.at("temperature"), "293");
    EXPECT_EQ(m.provenance.data_type, "formula 2");
    ASSERT_EQ(m.warnings.size(), 1u);
    EXPECT_TRUE(Contains(m.warnings[0], "k = 0"));
}

TEST(IoRefractiveIndexNOnly, PotassiumSutherland) {
    const fs::path file = kFixtures / "refractiveindex/K-Sutherland.yml";
    const Material m = load_refractiveindex_yaml(file);
    const Spectrum& n = tabulated(m.index.n);
    EXPECT_EQ(n.size(), 16u);
    EXPECT_NEAR(n.range().min_nm, 128.0, 1e-9);
    EXPECT_NEAR(n.range().max_nm, 313.1, 1e-9);
    EXPECT_EQ(n.values().front(), 0.964);
    EXPECT_EQ(m.index.k.kind(), "constant");
    EXPECT_EQ(m.index(200.0).imag(), 0.0);
    EXPECT_NEAR(m.index.range().min_nm, 128.0, 1e-9);
    EXPECT_NEAR(m.index.range().max_nm, 313.1, 1e-9);
    // No coverage of the visible range at all.
    EXPECT_FALSE(m.index.range().covers(kVisibleRange));
    EXPECT_EQ(n.count_in(kVisibleRange), 0u);
    ASSERT_EQ(m.warnings.size(), 1u);
    EXPECT_TRUE(Contains(m.warnings[0], "k = 0"));
    EXPECT_EQ(m.provenance.data_type, "tabulated n");
}

TEST(IoRefractiveIndexDuplicates, UnsortedWithIdenticalDuplicateEqualsJohnsonRows) {
    const Material m = load_refractiveindex_yaml(kFixtures / "valid-unsorted-duplicates.yml");
    const Material johnson = load_refractiveindex_yaml(kData / "nk/Au/Johnson.yml");
    const Spectrum& n = tabulated(m.index.n);
    const Spectrum& k = tabulated(m.index.k);
    ASSERT_EQ(n.size(), 23u);
    ASSERT_EQ(k.size(), 23u);
    EXPECT_EQ(n.identical_duplicates(), 1u);
    EXPECT_EQ(n.conflicting_duplicates(), 0u);
    EXPECT_EQ(k.identical_duplicates(), 1u);
    EXPECT_NEAR(n.range().min_nm, 300.9, 1e-9);
    EXPECT_NEAR(n.range().max_nm, 892.0, 1e-9);
    EXPECT_TRUE(m.index.range().covers(kVisibleRange));
    const Spectrum& jn = tabulated(johnson.index.n);
    const Spectrum& jk = tabulated(johnson.index.k);
    const std::size_t offset = index_of(jn, 300.9);
    ASSERT_LT(offset + 22, jn.size());
    for (std::size_t i = 0; i < 23; ++i) {
        EXPECT_EQ(n.wavelengths()[i], jn.wavelengths()[offset + i]) << i;
        EXPECT_EQ(n.values()[i], jn.values()[offset + i]) << i;
        EXPECT_EQ(k.wavelengths()[i], jk.wavelengths()[offset + i]) << i;
        EXPECT_EQ(k.values()[i], jk.values()[offset + i]) << i;
    }
    for (int nm = 360; nm <= 830; ++nm) EXPECT_EQ(m.index(nm), johnson.index(nm)) << nm;
    // PCHIP end slopes depend on the data set's ends, so the last interval (821.1–892 nm) of the
    // 23-row subset legitimately differs from the full table; every interval before it is the same.
    for (int nm = 360; nm <= 821; ++nm)
        EXPECT_EQ(m.index(nm, Interpolation::pchip), johnson.index(nm, Interpolation::pchip)) << nm;
    // Identical repeats are harmless: no conflict warning.
    for (const auto& w : m.warnings) EXPECT_FALSE(Contains(w, "mean")) << w;
}

TEST(IoRefractiveIndexDuplicates, ConflictingDuplicateUsesMeanAndWarns) {
    const fs::path file = kFixtures / "valid-conflicting-duplicate.yml";
    const Material m = load_refractiveindex_yaml(file);
    const Spectrum& n = tabulated(m.index.n);
    const Spectrum& k = tabulated(m.index.k);
    ASSERT_EQ(n.size(), 23u);
    ASSERT_EQ(k.size(), 23u);
    EXPECT_EQ(n.conflicting_duplicates(), 1u);
    EXPECT_EQ(k.conflicting_duplicates(), 1u);
    // Rows `0.5486 0.43 2.455` and `0.5486 0.53 2.555` → the mean.
    const std::size_t i = index_of(n, 548.6);
    ASSERT_LT(i, n.size());
    EXPECT_NEAR(n.values()[i], 0.48, 1e-12);
    EXPECT_NEAR(k.values()[index_of(k, 548.6)], 2.505, 1e-12);
    EXPECT_NEAR(m.index(548.6).real(), 0.48, 1e-9);
    EXPECT_NEAR(m.index(548.6).imag(), 2.505, 1e-9);
    // The other 22 rows are Johnson's.
    const Material johnson = load_refractiveindex_yaml(kData / "nk/Au/Johnson.yml");
    const Spectrum& jn = tabulated(johnson.index.n);
    const Spectrum& jk = tabulated(johnson.index.k);
    const std::size_t offset = index_of(jn, 300.9);
    for (std::size_t r = 0; r < 23; ++r) {
        EXPECT_EQ(n.wavelengths()[r], jn.wavelengths()[offset + r]) << r;
        if (r == i) continue;
        EXPECT_EQ(n.values()[r], jn.values()[offset + r]) << r;
        EXPECT_EQ(k.values()[r], jk.values()[offset + r]) << r;
    }
    // Not silent: a one-line warning naming the file, the count and the rule.
    ASSERT_FALSE(m.warnings.empty());
    bool found = false;
    for (const auto& w : m.warnings) {
        EXPECT_EQ(w.find('\n'), std::string::npos) << w;
        if (Contains(w, "mean") && Contains(w, "1 repeated wavelength") && Contains(w, file.string())) found = true;
    }
    EXPECT_TRUE(found) << "no warning names the file, '1 repeated wavelength' and 'mean': " << m.warnings.front();
}

TEST(IoRefractiveIndexShortRange, LoadsWithItsOwnRange) {
    // Not an import error: the coverage check belongs to fitting/rendering.
    const Material m = load_refractiveindex_yaml(kFixtures / "bad-short-range.yml");
    const Spectrum& n = tabulated(m.index.n);
    EXPECT_EQ(n.size(), 31u);
    EXPECT_NEAR(m.index.range().min_nm, 400.0, 1e-9);
    EXPECT_NEAR(m.index.range().max_nm, 700.0, 1e-9);
    EXPECT_FALSE(m.index.range().covers(kVisibleRange));
    EXPECT_NEAR(n.values().front(), 1.665616091, 1e-15);
    EXPECT_NEAR(tabulated(m.index.k).values().front(), 1.973924254, 1e-15);
}

// ---------------------------------------------------------------------------------------------
// Malformed files

struct Malformed {
    const char* file;
    std::vector<int> lines;  // accepted lines; empty: no line or line 1
    const char* field;       // expected substring naming the field ("" when none)
    const char* message;     // expected substring of the message ("" when none)
};

void PrintTo(const Malformed& m, std::ostream* os) { *os << m.file; }

class IoRefractiveIndexMalformed : public ::testing::TestWithParam<Malformed> {};

TEST_P(IoRefractiveIndexMalformed, ThrowsOneLineInputErrorNamingFileLineAndField) {
    const Malformed& c = GetParam();
    const fs::path file = kFixtures / c.file;
    ASSERT_TRUE(fs::exists(file)) << file;
    try {
        (void)load_refractiveindex_yaml(file);
        FAIL() << "expected InputError for " << file;
    } catch (const InputError& e) {
        const std::string what = e.what();
        EXPECT_EQ(what.find('\n'), std::string::npos) << what;
        EXPECT_EQ(what.find('\r'), std::string::npos) << what;
        EXPECT_TRUE(StartsWith(what, file.string()));
        EXPECT_EQ(e.location().file, file);
        if (c.lines.empty()) {
            // Whole-file defect: no line, or line 1.
            const bool no_line = StartsWith(what, file.string() + ": ");
            const bool line1 = StartsWith(what, file.string() + ":1: ");
            EXPECT_TRUE(no_line || line1) << what;
            EXPECT_LE(e.location().line, 1);
        } else {
            bool matched = false;
            for (int line : c.lines)
                if (StartsWith(what, file.string() + ":" + std::to_string(line) + ": ")) matched = true;
            EXPECT_TRUE(matched) << what;
            bool location_matched = false;
            for (int line : c.lines) location_matched = location_matched || e.location().line == line;
            EXPECT_TRUE(location_matched) << e.location().line;
        }
        if (*c.field != '\0') {
            EXPECT_TRUE(Contains(what, c.field));
            EXPECT_TRUE(Contains(e.location().field, c.field));
        }
        if (*c.message != '\0') {
            EXPECT_TRUE(Contains(what, c.message));
        }
    }
}

INSTANTIATE_TEST_SUITE_P(IoRefractiveIndex, IoRefractiveIndexMalformed,
                         ::testing::Values(Malformed{"bad-non-numeric.yml", {28}, "DATA[0].data", "1.2x3"},
                                           Malformed{"bad-negative-k.yml", {28}, "DATA[0].data", "-2.455"},
                                           Malformed{"bad-empty-data.yml", {12}, "DATA[0].data", ""},
                                           Malformed{"bad-no-data.yml", {}, "DATA", "missing"},
                                           Malformed{"bad-unknown-type.yml", {11}, "DATA[0].type", "tabulated xyz"},
                                           Malformed{"bad-truncated.yml", {12, 18}, "", ""},
                                           Malformed{"bad-wrong-columns.yml", {28}, "DATA[0].data", "found 2"}),
                         [](const ::testing::TestParamInfo<Malformed>& info) {
                             std::string name = info.param.file;
                             name = name.substr(0, name.find('.'));
                             for (char& ch : name)
                                 if (ch == '-') ch = '_';
                             return name;
                         });

TEST(IoRefractiveIndexMessages, NegativeKSaysNegative) {
    try {
        (void)load_refractiveindex_yaml(kFixtures / "bad-negative-k.yml");
        FAIL();
    } catch (const InputError& e) {
        EXPECT_TRUE(Contains(e.what(), "negative"));
        EXPECT_TRUE(Contains(e.what(), "k"));
    }
}

TEST(IoRefractiveIndexMessages, UnsupportedFormulaIsNamed) {
    TempDir dir;
    const fs::path file = dir.write("formula5.yml", "REFERENCES: test\n"
                                                    "DATA:\n"
                                                    "  - type: formula 5\n"
                                                    "    wavelength_range: 0.3 2.5\n"
                                                    "    coefficients: 1 2 3\n");
    try {
        (void)load_refractiveindex_yaml(file);
        FAIL() << "formula 5 must be refused";
    } catch (const InputError& e) {
        const std::string what = e.what();
        EXPECT_TRUE(Contains(what, "unsupported data type"));
        EXPECT_TRUE(Contains(what, "formula 5"));
        EXPECT_TRUE(StartsWith(what, file.string() + ":3: "));
        EXPECT_TRUE(Contains(what, "DATA[0].type"));
        EXPECT_EQ(what.find('\n'), std::string::npos);
    }
}

TEST(IoRefractiveIndexMessages, MissingFileIsAnInputError) {
    const fs::path file = kFixtures / "does-not-exist.yml";
    try {
        (void)load_refractiveindex_yaml(file);
        FAIL();
    } catch (const InputError& e) {
        EXPECT_TRUE(StartsWith(e.what(), file.string()));
    }
}

// ---------------------------------------------------------------------------------------------
// Every file of the built-in catalog

TEST(IoRefractiveIndexCatalog, EveryCatalogFileLoadsAndCoversTheVisible) {
    const Catalog catalog = Catalog::load(kData);
    ASSERT_FALSE(catalog.entries().empty());
    int files = 0;
    for (const CatalogEntry& entry : catalog.entries()) {
        std::vector<const CatalogSource*> sources{&entry.primary};
        for (const auto& a : entry.alternates) sources.push_back(&a);
        for (const CatalogSource* source : sources) {
            SCOPED_TRACE(entry.id + " / " + source->source + " (" + source->file.string() + ")");
            Material m;
            try {
                m = load_nk_file(source->file);
            } catch (const std::exception& e) {
                ADD_FAILURE() << e.what();
                continue;
            }
            ++files;
            EXPECT_EQ(m.provenance.sha256.size(), 64u);
            EXPECT_TRUE(m.index.range().covers(kVisibleRange))
                << m.index.range().min_nm << "–" << m.index.range().max_nm << " nm";
            int bad = 0;
            for (int nm = 360; nm <= 830 && bad < 3; ++nm) {
                try {
                    const std::complex<double> eta = m.index(nm);
                    if (!(std::isfinite(eta.real()) && std::isfinite(eta.imag()) && eta.real() >= 0.0 &&
                          eta.imag() >= 0.0)) {
                        ADD_FAILURE() << nm << " nm: n = " << eta.real() << ", k = " << eta.imag();
                        ++bad;
                    }
                } catch (const std::exception& e) {
                    ADD_FAILURE() << nm << " nm: " << e.what();
                    ++bad;
                }
            }
        }
    }
    EXPECT_GE(files, static_cast<int>(catalog_material_count()));
}

// ---------------------------------------------------------------------------------------------
// Rows no material has, far outside the visible range (issue 29: Lu and Garcia-Cortes's n < 0 in the infrared)

// Lines `first`–`last` (1-based, inclusive) of `file`: the same file with the rows after `last` deleted.
std::string lines_of(const fs::path& file, int first, int last) {
    std::istringstream in(read_file(file));
    std::string out;
    int number = 0;
    for (std::string line; std::getline(in, line);)
        if (++number >= first && number <= last) out += line + "\n";
    return out;
}

// The index of `a` and `b` identical at every nm of 360–830 (linear and pchip): the same reflectance there.
void expect_same_visible_index(const Material& a, const Material& b) {
    for (Interpolation interpolation : {Interpolation::linear, Interpolation::pchip})
        for (int nm = 360; nm <= 830; ++nm) {
            ASSERT_EQ(a.index.n(nm, interpolation, OutOfRange::error), b.index.n(nm, interpolation, OutOfRange::error));
            ASSERT_EQ(a.index.k(nm, interpolation, OutOfRange::error), b.index.k(nm, interpolation, OutOfRange::error));
        }
}

TEST(IoRefractiveIndexUnphysicalRows, InfraredNegativeNIsDroppedWithOneWarning) {
    TempDir dir;
    const fs::path file = kFixtures / "drop-ir-negative-n.yml";
    const Material m = load_refractiveindex_yaml(file);
    ASSERT_EQ(m.warnings.size(), 1u);
    EXPECT_EQ(m.warnings[0], file.string() +
                                 ":52: DATA[0].data: negative refractive index n = -0.35 at 1.216 \xc2\xb5m: rows from "
                                 "1.216 \xc2\xb5m on are not used (colour needs 360\xe2\x80\x93"
                                 "830 nm; n and k kept "
                                 "over 0.1879\xe2\x80\x93"
                                 "1.088 \xc2\xb5m)");
    // The independent form: the file without its lines 52–55 (the four rows from 1.216 µm on).
    const Material trimmed = load_refractiveindex_yaml(dir.write("trimmed.yml", lines_of(file, 1, 51)));
    EXPECT_TRUE(trimmed.warnings.empty());
    EXPECT_TRUE(std::ranges::equal(tabulated(m.index.n).wavelengths(), tabulated(trimmed.index.n).wavelengths()));
    EXPECT_TRUE(std::ranges::equal(tabulated(m.index.k).values(), tabulated(trimmed.index.k).values()));
    EXPECT_DOUBLE_EQ(tabulated(m.index.n).range().max_nm, 1088.0);
    expect_same_visible_index(m, trimmed);
}

TEST(IoRefractiveIndexUnphysicalRows, NegativeNInsideTheVisibleRangeIsRefusedAsBefore) {
    TempDir dir;
    std::string text = read_file(kFixtures / "drop-ir-negative-n.yml");
    text.replace(text.find("0.5486 0.43"), 11, "0.5486 -0.43");  // line 42
    const fs::path file = dir.write("inside.yml", text);
    try {
        (void)load_refractiveindex_yaml(file);
        FAIL() << "expected InputError";
    } catch (const InputError& e) {
        EXPECT_EQ(std::string(e.what()), file.string() + ":42: DATA[0].data: negative refractive index n = -0.43");
    }
}

TEST(IoRefractiveIndexUnphysicalRows, ABadRowBracketingTheRangeIsRefused) {
    // n < 0 from 0.892 µm on: the last valid row is 0.8211 µm, so 830 nm would need the bad row to interpolate.
    TempDir dir;
    std::string text = read_file(kFixtures / "drop-ir-negative-n.yml");
    text.replace(text.find("0.8920 0.17"), 11, "0.8920 -0.17");  // line 49
    const fs::path file = dir.write("bracket.yml", text);
    try {
        (void)load_refractiveindex_yaml(file);
        FAIL() << "expected InputError";
    } catch (const InputError& e) {
        EXPECT_EQ(std::string(e.what()), file.string() + ":49: DATA[0].data: negative refractive index n = -0.17");
    }
}

TEST(IoRefractiveIndexUnphysicalRows, UltravioletRowsAreDroppedToo) {
    // k < 0 at 0.2214 µm (line 15 of the fixture): rows up to it go, 0.2262 µm on stay.
    TempDir dir;
    std::string text = read_file(kFixtures / "drop-ir-negative-n.yml");
    text.replace(text.find("0.2214 1.30 1.427"), 17, "0.2214 1.30 -1.427");
    const fs::path file = dir.write("uv.yml", text);
    const Material m = load_refractiveindex_yaml(file);
    ASSERT_EQ(m.warnings.size(), 2u);
    EXPECT_TRUE(StartsWith(m.warnings[0], file.string() + ":15: DATA[0].data: negative extinction coefficient k = "
                                                          "-1.427 at 0.2214 \xc2\xb5m: rows up to 0.2214 \xc2\xb5m "
                                                          "are not used"))
        << m.warnings[0];
    EXPECT_TRUE(Contains(m.warnings[0], "kept over 0.2262\xe2\x80\x93"
                                        "1.088 \xc2\xb5m"))
        << m.warnings[0];
    EXPECT_TRUE(Contains(m.warnings[1], ":52: ")) << m.warnings[1];
    // The independent form: lines 1–6 and 16–51 (the rows from 0.2262 to 1.088 µm).
    const Material trimmed =
        load_refractiveindex_yaml(dir.write("trimmed.yml", lines_of(file, 1, 6) + lines_of(file, 16, 51)));
    EXPECT_TRUE(trimmed.warnings.empty());
    EXPECT_TRUE(std::ranges::equal(tabulated(m.index.n).wavelengths(), tabulated(trimmed.index.n).wavelengths()));
    EXPECT_DOUBLE_EQ(tabulated(m.index.n).range().min_nm, 226.2);
    expect_same_visible_index(m, trimmed);
}

}  // namespace test_io_refractiveindex
}  // namespace metalfit
