// Importer for user n,k tables in CSV, and extension dispatch.
#include <gtest/gtest.h>

#include "test_support.hpp"

#include <unistd.h>

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <string>

#include "libfit/base/errors.hpp"
#include "libfit/io/csv.hpp"
#include "libfit/io/refractiveindex.hpp"

namespace metalfit {
namespace test_io_csv {

using namespace metalfit::test;

namespace fs = std::filesystem;

TEST(IoCsv, NanometreAndMicrometreFilesGiveTheSameSpectrumAsJohnson) {
    const Material nm = load_nk_csv(kFixtures / "valid-nk.csv");
    const Material um = load_nk_csv(kFixtures / "valid-um.csv");
    const Material johnson = load_refractiveindex_yaml(kData / "nk/Au/Johnson.yml");
    const Spectrum& n_nm = tabulated(nm.index.n);
    const Spectrum& k_nm = tabulated(nm.index.k);
    const Spectrum& n_um = tabulated(um.index.n);
    const Spectrum& k_um = tabulated(um.index.k);
    const Spectrum& jn = tabulated(johnson.index.n);
    const Spectrum& jk = tabulated(johnson.index.k);
    ASSERT_EQ(n_nm.size(), 23u);
    ASSERT_EQ(k_nm.size(), 23u);
    ASSERT_EQ(n_um.size(), 23u);
    ASSERT_EQ(k_um.size(), 23u);
    EXPECT_NEAR(n_nm.range().min_nm, 300.9, 1e-9);
    EXPECT_NEAR(n_nm.range().max_nm, 892.0, 1e-9);
    EXPECT_NEAR(n_um.range().min_nm, 300.9, 1e-9);
    EXPECT_NEAR(n_um.range().max_nm, 892.0, 1e-9);
    const std::size_t offset = index_of(jn, 300.9);
    ASSERT_LT(offset + 22, jn.size());
    for (std::size_t i = 0; i < 23; ++i) {
        // Wavelengths: λ (nm) vs λ (µm) × 1000 may differ in the last bit only.
        EXPECT_NEAR(n_nm.wavelengths()[i], n_um.wavelengths()[i], 1e-9) << i;
        EXPECT_NEAR(n_nm.wavelengths()[i], jn.wavelengths()[offset + i], 1e-9) << i;
        EXPECT_NEAR(k_nm.wavelengths()[i], jk.wavelengths()[offset + i], 1e-9) << i;
        // Values are the same decimal numbers: exactly equal.
        EXPECT_EQ(n_nm.values()[i], n_um.values()[i]) << i;
        EXPECT_EQ(k_nm.values()[i], k_um.values()[i]) << i;
        EXPECT_EQ(n_nm.values()[i], jn.values()[offset + i]) << i;
        EXPECT_EQ(k_nm.values()[i], jk.values()[offset + i]) << i;
    }
    for (int w = 360; w <= 830; ++w) {
        EXPECT_NEAR(nm.index(w).real(), um.index(w).real(), 1e-12) << w;
        EXPECT_NEAR(nm.index(w).imag(), um.index(w).imag(), 1e-12) << w;
        EXPECT_NEAR(nm.index(w).real(), johnson.index(w).real(), 1e-12) << w;
        EXPECT_NEAR(nm.index(w).imag(), johnson.index(w).imag(), 1e-12) << w;
    }
    // Row `548.6,0.43,2.455`.
    EXPECT_EQ(n_nm.values()[index_of(n_nm, 548.6)], 0.43);
    EXPECT_EQ(k_nm.values()[index_of(k_nm, 548.6)], 2.455);
    EXPECT_EQ(nm.provenance.format, "CSV");
    EXPECT_EQ(nm.provenance.sha256.size(), 64u);
    EXPECT_NE(nm.provenance.sha256, um.provenance.sha256);
    EXPECT_EQ(nm.id, "valid-nk");
    EXPECT_TRUE(nm.warnings.empty());
}

struct BadCsv {
    const char* file;
    int line;
    const char* message;
};

void PrintTo(const BadCsv& b, std::ostream* os) { *os << b.file; }

class IoCsvMalformed : public ::testing::TestWithParam<BadCsv> {};

TEST_P(IoCsvMalformed, ThrowsInputErrorNamingFileAndLine) {
    const BadCsv& c = GetParam();
    const fs::path file = kFixtures / c.file;
    ASSERT_TRUE(fs::exists(file)) << file;
    try {
        (void)load_nk_csv(file);
        FAIL() << "expected InputError for " << file;
    } catch (const InputError& e) {
        const std::string what = e.what();
        EXPECT_TRUE(StartsWith(what, file.string() + ":" + std::to_string(c.line) + ": "));
        EXPECT_EQ(e.location().line, c.line);
        EXPECT_EQ(what.find('\n'), std::string::npos) << what;
        EXPECT_TRUE(Contains(what, c.message));
    }
}

INSTANTIATE_TEST_SUITE_P(IoCsv, IoCsvMalformed,
                         ::testing::Values(BadCsv{"bad-header.csv", 1, "wavelength_nm,n,k"},
                                           BadCsv{"bad-row.csv", 17, "abc"},
                                           BadCsv{"bad-negative-k.csv", 17, "negative"}),
                         [](const ::testing::TestParamInfo<BadCsv>& info) {
                             std::string name = info.param.file;
                             name = name.substr(0, name.find('.'));
                             for (char& ch : name)
                                 if (ch == '-') ch = '_';
                             return name;
                         });

TEST(IoCsv, CommentsAndBlankLinesAreIgnoredAndLinesStillCounted) {
    TempDir dir;
    const fs::path file = dir.write("table.csv", "# a comment\n"
                                                 "\n"
                                                 "wavelength_nm,n,k\n"
                                                 "400,1.5,2.0\n"
                                                 "# another\n"
                                                 "500,1.0,3.0\n"
                                                 "\n"
                                                 "600,x,4.0\n");
    try {
        (void)load_nk_csv(file);
        FAIL();
    } catch (const InputError& e) {
        EXPECT_TRUE(StartsWith(e.what(), file.string() + ":8: "));
    }
    const fs::path good = dir.write("good.csv", "# c\nwavelength_nm,n,k\n\n400,1.5,2.0\n# x\n500,1.0,3.0\n");
    const Material m = load_nk_csv(good);
    EXPECT_EQ(tabulated(m.index.n).size(), 2u);
    EXPECT_DOUBLE_EQ(m.index(450.0).real(), 1.25);
    EXPECT_DOUBLE_EQ(m.index(450.0).imag(), 2.5);
}

TEST(IoCsv, LoadNkFileDispatchesOnExtension) {
    const Material csv = load_nk_file(kFixtures / "valid-nk.csv");
    EXPECT_EQ(csv.provenance.format, "CSV");
    const Material yml = load_nk_file(kFixtures / "valid-unsorted-duplicates.yml");
    EXPECT_EQ(yml.provenance.format, "refractiveindex.info YAML");
    EXPECT_EQ(tabulated(yml.index.n).size(), 23u);

    TempDir dir;
    const std::string contents = read_file(kFixtures / "valid-nk.csv");
    ASSERT_FALSE(contents.empty());
    // Upper-case extensions are the same extension.
    const Material upper = load_nk_file(dir.write("UPPER.CSV", contents));
    EXPECT_EQ(upper.provenance.format, "CSV");
    EXPECT_EQ(tabulated(upper.index.n).size(), 23u);
    // A .yaml extension goes to the YAML reader.
    const Material yaml = load_nk_file(dir.write("copy.yaml", read_file(kFixtures / "valid-unsorted-duplicates.yml")));
    EXPECT_EQ(yaml.provenance.format, "refractiveindex.info YAML");
}

TEST(IoCsv, LoadNkFileRejectsUnknownExtension) {
    TempDir dir;
    const fs::path sheet = dir.write("table.xlsx", read_file(kFixtures / "valid-nk.csv"));
    try {
        (void)load_nk_file(sheet);
        FAIL() << "a .xlsx file must be refused";
    } catch (const InputError& e) {
        const std::string what = e.what();
        EXPECT_TRUE(StartsWith(what, sheet.string()));
        EXPECT_TRUE(Contains(what, ".xlsx"));
        EXPECT_EQ(what.find('\n'), std::string::npos);
    }
    EXPECT_THROW((void)load_nk_file(dir.path() / "no-extension"), InputError);
}

TEST(IoCsv, MissingFileIsAnInputError) {
    const fs::path file = kFixtures / "does-not-exist.csv";
    try {
        (void)load_nk_file(file);
        FAIL();
    } catch (const InputError& e) {
        EXPECT_TRUE(StartsWith(e.what(), file.string()));
    }
}

TEST(IoCsv, HeaderOnlyFileIsAnInputError) {
    TempDir dir;
    const fs::path file = dir.write("empty.csv", "wavelength_nm,n,k\n");
    try {
        (void)load_nk_csv(file);
        FAIL();
    } catch (const InputError& e) {
        EXPECT_TRUE(StartsWith(e.what(), file.string()));
    }
}

// Instrument-style files (tests/fixtures/README.md): each holds the rows of valid-nk.csv (Johnson & Christy's Au,
// 300.9–892 nm) in another layout, so each must load to the same n and k.
void expect_same_rows_as_valid_nk(const Material& m, double tolerance, bool k_without_first_row = false) {
    const Material reference = load_nk_csv(kFixtures / "valid-nk.csv");
    const Spectrum& rn = tabulated(reference.index.n);
    const Spectrum& rk = tabulated(reference.index.k);
    const Spectrum& n = tabulated(m.index.n);
    const Spectrum& k = tabulated(m.index.k);
    ASSERT_EQ(n.size(), rn.size());
    ASSERT_EQ(k.size(), rk.size() - (k_without_first_row ? 1 : 0));
    for (std::size_t i = 0; i < n.size(); ++i) {
        EXPECT_NEAR(n.wavelengths()[i], rn.wavelengths()[i], 1e-5 * rn.wavelengths()[i]) << i;
        EXPECT_NEAR(n.values()[i], rn.values()[i], tolerance) << i;
    }
    const std::size_t offset = k_without_first_row ? 1 : 0;
    for (std::size_t i = 0; i < k.size(); ++i) {
        EXPECT_NEAR(k.wavelengths()[i], rk.wavelengths()[i + offset], 1e-5 * rk.wavelengths()[i + offset]) << i;
        EXPECT_NEAR(k.values()[i], rk.values()[i + offset], tolerance) << i;
    }
}

TEST(IoTable, ByteOrderMarkAndCrlfLineEndsAreAccepted) {
    const Material m = load_nk_file(kFixtures / "instrument-bom-crlf.csv");
    expect_same_rows_as_valid_nk(m, 0.0);
    EXPECT_EQ(m.provenance.format, "CSV");
    EXPECT_TRUE(m.warnings.empty());
}

TEST(IoTable, TabSeparatedWithUnitInBracketsAndAnExtraColumn) {
    const Material m = load_nk_file(kFixtures / "instrument-tab.tsv");
    expect_same_rows_as_valid_nk(m, 0.0);
    EXPECT_EQ(m.provenance.format, "table (tab-separated)");
    ASSERT_EQ(m.warnings.size(), 1u);
    EXPECT_TRUE(Contains(m.warnings[0], "instrument-tab.tsv:2: column 'MSE' ignored")) << m.warnings[0];
}

TEST(IoTable, SemicolonsWithDecimalCommasInMicrometres) {
    const Material m = load_nk_file(kFixtures / "instrument-semicolon.txt");
    expect_same_rows_as_valid_nk(m, 0.0);
    EXPECT_EQ(m.provenance.format, "table (semicolon-separated)");
}

TEST(IoTable, PhotonEnergyAndDielectricFunctionAreConvertedToWavelengthAndNk) {
    // E = hc/λ with hc = 1239.84198 eV nm, ε₁ = n² − k², ε₂ = 2nk, written with 9 significant digits: n and k
    // come back to 1e-7 (the inverse map n = √((|ε| + ε₁)/2), k = √((|ε| − ε₁)/2)).
    const Material m = load_nk_file(kFixtures / "instrument-energy-eps.dat");
    expect_same_rows_as_valid_nk(m, 1e-7);
    EXPECT_EQ(m.provenance.data_type, "tabulated e1 e2 (converted to n, k)");
}

TEST(IoTable, RefractiveIndexInfoDownloadHasAnNBlockThenAKBlock) {
    const Material m = load_nk_file(kFixtures / "refractiveindex-download.csv");
    expect_same_rows_as_valid_nk(m, 0.0, /*k_without_first_row=*/true);
    EXPECT_EQ(m.provenance.data_type, "tabulated n + tabulated k");
}

TEST(IoTable, AFileWithoutKAssumesZeroAndSaysSo) {
    TempDir dir;
    const Material m = load_nk_file(dir.write("n-only.csv", "wl,n\n0.3,1.5\n0.9,1.5\n"));
    EXPECT_EQ(m.index(500.0).imag(), 0.0);
    ASSERT_EQ(m.warnings.size(), 1u);
    EXPECT_TRUE(Contains(m.warnings[0], "k = 0 assumed"));
}

struct BadTable {
    const char* file;
    int line;
    const char* message;
};

void PrintTo(const BadTable& b, std::ostream* os) { *os << b.file; }

class IoTableMalformed : public ::testing::TestWithParam<BadTable> {};

TEST_P(IoTableMalformed, ThrowsOneLineNamingFileAndLine) {
    const BadTable& c = GetParam();
    const fs::path file = kFixtures / c.file;
    ASSERT_TRUE(fs::exists(file)) << file;
    try {
        (void)load_nk_file(file);
        FAIL() << "expected InputError for " << file;
    } catch (const InputError& e) {
        const std::string what = e.what();
        EXPECT_TRUE(StartsWith(what, file.string() + ":" + std::to_string(c.line) + ": ")) << what;
        EXPECT_EQ(what.find('\n'), std::string::npos) << what;
        EXPECT_TRUE(Contains(what, c.message)) << what;
    }
}

INSTANTIATE_TEST_SUITE_P(IoTable, IoTableMalformed,
                         ::testing::Values(BadTable{"bad-unit.tsv", 1, "unknown unit 'furlong'"},
                                           BadTable{"bad-missing-field.tsv", 9, "expected 3 fields"},
                                           BadTable{"bad-negative-eps2.txt", 10, "negative"}),
                         [](const ::testing::TestParamInfo<BadTable>& info) {
                             std::string name = info.param.file;
                             name = name.substr(0, name.find('.'));
                             for (char& ch : name)
                                 if (ch == '-') ch = '_';
                             return name;
                         });

TEST(IoTable, HeadersThatCannotBeReadSayWhatIsExpected) {
    TempDir dir;
    const auto message = [&](const std::string& name, const std::string& text) {
        try {
            (void)load_nk_file(dir.write(name, text));
        } catch (const InputError& e) {
            return std::string(e.what());
        }
        return std::string("no error");
    };
    EXPECT_TRUE(Contains(message("no-unit.csv", "wavelength,n,k\n500,1,2\n"), "does not say its unit"));
    EXPECT_TRUE(Contains(message("energy.csv", "energy,e1,e2\n2,1,2\n"), "does not say its unit"));
    EXPECT_TRUE(Contains(message("mixed.csv", "wavelength_nm,n,e2\n500,1,2\n"), "one pair"));
    EXPECT_TRUE(Contains(message("no-header.dat", "500 1 2\n"), ":1: a data row before any header line"));
    EXPECT_TRUE(Contains(message("two-x.csv", "wavelength_nm,energy (eV),n,k\n500,2.4,1,2\n"), "more than one"));
}

// ---------------------------------------------------------------------------------------------
// Rows no material has, far outside the visible range (issue 29): dropped from there outward, with one warning

// Lines `first`–`last` (1-based, inclusive) of `file`.
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

TEST(IoCsvUnphysicalRows, InfraredNegativeNIsDroppedWithOneWarning) {
    TempDir dir;
    const fs::path file = kFixtures / "drop-ir-negative-n.csv";
    const Material m = load_nk_csv(file);
    ASSERT_EQ(m.warnings.size(), 1u);
    EXPECT_EQ(m.warnings[0], file.string() +
                                 ":48: negative refractive index n = -0.35 at 1216 nm: rows from 1216 nm on are not "
                                 "used (colour needs 360\xe2\x80\x93"
                                 "830 nm; n and k kept over 187.9\xe2\x80\x93"
                                 "1088 nm)");
    // The independent form: the file without its lines 48–51 (the rows from 1216 nm on).
    const Material trimmed = load_nk_csv(dir.write("trimmed.csv", lines_of(file, 1, 47)));
    EXPECT_TRUE(trimmed.warnings.empty());
    EXPECT_TRUE(std::ranges::equal(tabulated(m.index.n).wavelengths(), tabulated(trimmed.index.n).wavelengths()));
    EXPECT_TRUE(std::ranges::equal(tabulated(m.index.k).values(), tabulated(trimmed.index.k).values()));
    expect_same_visible_index(m, trimmed);
    // And the YAML form of the same rows (µm × 1000 is within an ulp of the nm written here).
    const Material yaml = load_refractiveindex_yaml(kFixtures / "drop-ir-negative-n.yml");
    for (int nm = 360; nm <= 830; ++nm) {
        EXPECT_NEAR(m.index(nm).real(), yaml.index(nm).real(), 1e-12) << nm;
        EXPECT_NEAR(m.index(nm).imag(), yaml.index(nm).imag(), 1e-12) << nm;
    }
}

TEST(IoCsvUnphysicalRows, NegativeNInsideTheVisibleRangeIsRefusedAsBefore) {
    TempDir dir;
    std::string text = read_file(kFixtures / "drop-ir-negative-n.csv");
    text.replace(text.find("548.6,0.43"), 10, "548.6,-0.43");
    const fs::path file = dir.write("inside.csv", text);
    try {
        (void)load_nk_csv(file);
        FAIL() << "expected InputError";
    } catch (const InputError& e) {
        EXPECT_EQ(std::string(e.what()), file.string() + ":38: negative refractive index n = -0.43");
    }
}

TEST(IoCsvUnphysicalRows, UltravioletNegativeEps2IsDropped) {
    // ε₂ < 0 at 3.62 eV (342.5 nm, line 6): the rows above 3.5 eV go; 354.2 nm brackets 360 nm.
    TempDir dir;
    const fs::path file = kFixtures / "drop-uv-negative-eps2.txt";
    const Material m = load_nk_csv(file);
    ASSERT_EQ(m.warnings.size(), 1u);
    EXPECT_TRUE(StartsWith(m.warnings[0], file.string() + ":6: negative \xce\xb5\xe2\x82\x82 = -5.53816 (absorption "
                                                          "must be >= 0) at 342.5 nm: rows up to 342.5 nm are not "
                                                          "used (colour needs 360\xe2\x80\x93"
                                                          "830 nm; n and k kept over 354.2\xe2\x80\x93"))
        << m.warnings[0];
    const Material trimmed = load_nk_csv(dir.write("trimmed.txt", lines_of(file, 1, 1) + lines_of(file, 7, 24)));
    EXPECT_TRUE(trimmed.warnings.empty());
    EXPECT_TRUE(std::ranges::equal(tabulated(m.index.n).wavelengths(), tabulated(trimmed.index.n).wavelengths()));
    expect_same_visible_index(m, trimmed);
}

}  // namespace test_io_csv
}  // namespace metalfit
