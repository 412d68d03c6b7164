// Reference curves R_c(μ): white balance, known metal colours, and an independent evaluator.
#include <gtest/gtest.h>

#include "test_support.hpp"

#include <Eigen/Dense>

#include <filesystem>
#include <fstream>

#include "libfit/base/errors.hpp"
#include "libfit/io/catalog.hpp"
#include "libfit/io/csv.hpp"
#include "libfit/optics/fresnel.hpp"
#include "libfit/reference/reference_curve.hpp"

namespace metalfit {
namespace test_reference_curve {

using namespace metalfit::test;

const OcioConfigChoice kShipped{kData / "ocio" / "config.ocio", "test"};

class ReferenceCurveTest : public ::testing::Test {
protected:
    static void SetUpTestSuite() { catalog_ = new Catalog(Catalog::load(kData)); }
    static void TearDownTestSuite() { delete catalog_; }

    static ReferenceCurve curve(const Material& m, const std::string& space = {}, Observer o = Observer::cie1931_2deg,
                                Illuminant i = Illuminant::D65, SpectralOptions options = {}) {
        return ReferenceCurve(m, Colorimetry::load(kData, o, i), ColorSpaceConverter::create(kShipped, space), options);
    }
    static Material material(const std::string& name) { return load_material(*catalog_, name); }

    static Catalog* catalog_;
};
Catalog* ReferenceCurveTest::catalog_ = nullptr;

TEST_F(ReferenceCurveTest, GrazingIsWhiteInEverySpaceObserverAndIlluminant) {
    const Material gold = material("gold");
    for (const char* space : {"", "ACEScg", "Linear P3-D65", "Linear Rec.2020", "ACES2065-1"})
        for (Observer o : {Observer::cie1931_2deg, Observer::cie1964_10deg})
            for (Illuminant i : {Illuminant::D65, Illuminant::A, Illuminant::E}) {
                const RGB r0 = curve(gold, space, o, i)(0.0);
                for (int c = 0; c < 3; ++c) EXPECT_NEAR(r0[c], 1.0, 1e-6) << space << " " << to_string(i) << " " << c;
            }
}

TEST_F(ReferenceCurveTest, KnownMetalColoursAtNormalIncidence) {
    const RGB gold = curve(material("Au"))(1.0);  // Johnson & Christy
    EXPECT_NEAR(gold.r, 1.04, 0.01);
    EXPECT_NEAR(gold.g, 0.73, 0.01);
    EXPECT_NEAR(gold.b, 0.36, 0.01);
    EXPECT_GT(gold.r, 1.0) << "gold's red F0 lies outside Linear Rec.709 and must not be clamped";
    const RGB aluminium = curve(material("Al"))(1.0);  // McPeak
    EXPECT_NEAR(aluminium.r, 0.91, 0.01);
    EXPECT_NEAR(aluminium.g, 0.92, 0.01);
    EXPECT_NEAR(aluminium.b, 0.92, 0.01);
}

// An independent evaluator of the shared definitions: the thesis' real-form Fresnel per wavelength,
// hand-rolled linear interpolation of the file's rows, the CIE tables read here, and the Rec.709
// matrix from primaries in double precision (no OCIO).
RGB independent_rgb(const Spectrum& n, const Spectrum& k, double mu) {
    auto read = [](const std::string& name, int columns) {
        std::ifstream in(kData / "cie" / name);
        std::string line;
        std::getline(in, line);  // header
        std::vector<std::vector<double>> rows;
        for (char comma; std::getline(in, line);) {
            std::istringstream s(line);
            std::vector<double> row(static_cast<std::size_t>(columns) + 1);
            s >> row[0];
            for (int c = 1; c <= columns; ++c) s >> comma >> row[static_cast<std::size_t>(c)];
            rows.push_back(row);
        }
        return rows;
    };
    const auto cmf = read("cie1931_2deg_cmf.csv", 3);
    const auto d65 = read("cie_illuminant_D65.csv", 1);
    auto lerp = [](const Spectrum& s, double nm) {
        const auto w = s.wavelengths();
        const auto v = s.values();
        std::size_t i = 0;
        while (w[i + 1] < nm) ++i;
        return v[i] + (v[i + 1] - v[i]) * (nm - w[i]) / (w[i + 1] - w[i]);
    };
    auto fresnel_real = [](double m, double nn, double kk) {
        if (m == 1.0) return ((nn - 1) * (nn - 1) + kk * kk) / ((nn + 1) * (nn + 1) + kk * kk);
        const double s2 = 1 - m * m, t = nn * nn - kk * kk - s2, root = std::sqrt(t * t + 4 * nn * nn * kk * kk);
        const double a2 = 0.5 * (root + t), b2 = 0.5 * (root - t), a = std::sqrt(a2), q = s2 / m;
        const double fs = (a2 + b2 - 2 * a * m + m * m) / (a2 + b2 + 2 * a * m + m * m);
        return 0.5 * (fs + fs * (a2 + b2 - 2 * a * q + q * q) / (a2 + b2 + 2 * a * q + q * q));
    };
    Eigen::Vector3d xyz = Eigen::Vector3d::Zero(), white = Eigen::Vector3d::Zero();
    for (const auto& row : cmf) {
        const double nm = row[0];
        const double illuminant = d65[static_cast<std::size_t>(nm - 300.0)][1];
        const Eigen::Vector3d w(illuminant * row[1], illuminant * row[2], illuminant * row[3]);
        xyz += fresnel_real(mu, lerp(n, nm), lerp(k, nm)) * w;
        white += w;
    }
    const double primaries[3][2] = {{0.64, 0.33}, {0.30, 0.60}, {0.15, 0.06}};
    Eigen::Matrix3d m;
    for (int c = 0; c < 3; ++c)
        m.col(c) = Eigen::Vector3d(primaries[c][0] / primaries[c][1], 1.0,
                                   (1 - primaries[c][0] - primaries[c][1]) / primaries[c][1]);
    m = m * m.colPivHouseholderQr()
                .solve(Eigen::Vector3d(0.3127 / 0.3290, 1.0, (1 - 0.3127 - 0.3290) / 0.3290))
                .asDiagonal();
    const Eigen::Vector3d rgb = m.inverse() * xyz, rgb_white = m.inverse() * white;
    return {rgb(0) / rgb_white(0), rgb(1) / rgb_white(1), rgb(2) / rgb_white(2)};
}

TEST_F(ReferenceCurveTest, AgreesWithAnIndependentEvaluator) {
    for (const char* name : {"Au", "Cu", "Al", "Ag", "TiN", "Cu-Zn", "Cr"}) {
        const Material m = material(name);
        const ReferenceCurve r = curve(m);
        for (double mu : {1.0, kMuF82, 0.5, 0.1}) {
            const RGB expected = independent_rgb(*m.index.n.tabulated(), *m.index.k.tabulated(), mu);
            const RGB actual = r(mu);
            for (int c = 0; c < 3; ++c) EXPECT_NEAR(actual[c], expected[c], 2e-6) << name << " mu=" << mu << " c=" << c;
        }
    }
}

// The curve integrates the real Fresnel form (optics/fresnel_real.hpp); the complex form of optics/fresnel.hpp,
// integrated with the colorimetry's own 1 nm summation, gives the same XYZ to 1e-12 relative on every catalog
// material; a batch of μ gives exactly what single calls give.
TEST_F(ReferenceCurveTest, RealFormIntegralMatchesTheComplexFormOnEveryCatalogMaterial) {
    const Colorimetry colorimetry = Colorimetry::load(kData, Observer::cie1931_2deg, Illuminant::D65);
    const ColorSpaceConverter converter = ColorSpaceConverter::create(kShipped, "");
    std::vector<double> mus;
    for (int i = 0; i <= 20; ++i) mus.push_back(i / 20.0);
    mus.push_back(kMuF82);
    for (const CatalogEntry& entry : catalog_->entries()) {
        const Material m = load_material(*catalog_, entry.id);
        const ReferenceCurve r(m, colorimetry, converter);
        const DenseSpectrum<XYZ>& grid = colorimetry.weights();
        const auto eta = DenseSpectrum<std::complex<double>>::sampled(grid.first_nm(), grid.last_nm(), [&](int nm) {
            return m.index(nm, Interpolation::linear, OutOfRange::error);
        });
        const std::vector<XYZ> batch = r.xyz(std::span<const double>(mus));
        ASSERT_EQ(batch.size(), mus.size());
        for (std::size_t j = 0; j < mus.size(); ++j) {
            const double mu = mus[j];
            const XYZ expected =
                colorimetry.integrate(eta.map([mu](const std::complex<double>& e) { return fresnel(mu, e); }));
            const XYZ single = r.xyz(mu);
            for (int c = 0; c < 3; ++c) {
                EXPECT_LE(std::abs(single[c] - expected[c]), 1e-12 * std::abs(expected[c]))
                    << entry.id << " mu=" << mu << " c=" << c;
                EXPECT_EQ(batch[j][c], single[c]) << entry.id << " mu=" << mu;
            }
        }
    }
}

std::filesystem::path write_csv(const std::string& name, double n, double k) {
    const auto path = std::filesystem::temp_directory_path() / name;
    std::ofstream out(path);
    out << "wavelength_nm,n,k\n300," << n << "," << k << "\n900," << n << "," << k << "\n";
    return path;
}

TEST_F(ReferenceCurveTest, SpectrallyFlatMaterialsAreGreyWithTheirOwnReflectance) {
    // A wavelength-independent reflectance ρ gives R_c = ρ in every channel (white balance).
    const auto glass = write_csv("metalfit-glass.csv", 1.5, 0.0);
    const ReferenceCurve r = curve(load_nk_file(glass), "ACEScg");
    for (double mu : {1.0, 0.6, 0.2}) {
        const double f = fresnel(mu, {1.5, 0.0});
        const RGB rgb = r(mu);
        for (int c = 0; c < 3; ++c) EXPECT_NEAR(rgb[c], f, 2e-7) << mu;
    }
    EXPECT_NEAR(r(1.0).g, 0.04, 1e-7);
    const auto vacuum = write_csv("metalfit-vacuum.csv", 1.0, 0.0);
    const ReferenceCurve none = curve(load_nk_file(vacuum));
    for (double mu : {1.0, 0.5, 1e-6}) EXPECT_EQ(none(mu).max(), 0.0) << mu;
    std::filesystem::remove(glass);
    std::filesystem::remove(vacuum);
}

TEST_F(ReferenceCurveTest, DataNotCoveringTheVisibleRangeIsAnErrorNamingTheFile) {
    const auto file = kFixtures / "bad-short-range.yml";
    const Material m = load_nk_file(file);
    try {
        curve(m);
        FAIL() << "no error for data covering only 400–700 nm";
    } catch (const InputError& e) {
        const std::string what = e.what();
        EXPECT_EQ(what.rfind(file.string(), 0), 0u) << what;
        EXPECT_NE(what.find("DATA"), std::string::npos) << what;
        EXPECT_NE(what.find("400"), std::string::npos) << what;
        EXPECT_NE(what.find("360"), std::string::npos) << what;
        EXPECT_NE(what.find("n covers"), std::string::npos) << what;  // the quantity that fails
        EXPECT_NE(what.find("--extrapolate"), std::string::npos) << what;
    }
    // Asked for explicitly, end values are held outside the data, and the curve says where.
    const ReferenceCurve extrapolated =
        curve(m, {}, Observer::cie1931_2deg, Illuminant::D65, {Interpolation::linear, OutOfRange::clamp});
    EXPECT_GT(extrapolated(1.0).r, 0.9);
    EXPECT_EQ(
        extrapolated.held_constant(),
        (std::vector<std::string>{"n held at its 400 nm value over 360–400 nm (--extrapolate; measured 400–700 nm)",
                                  "n held at its 700 nm value over 700–830 nm (--extrapolate; measured 400–700 nm)",
                                  "k held at its 400 nm value over 360–400 nm (--extrapolate; measured 400–700 nm)",
                                  "k held at its 700 nm value over 700–830 nm (--extrapolate; measured 400–700 nm)"}));
    // Data that cover the grid hold nothing, with or without --extrapolate.
    EXPECT_TRUE(
        curve(material("Au"), {}, Observer::cie1931_2deg, Illuminant::D65, {Interpolation::linear, OutOfRange::clamp})
            .held_constant()
            .empty());
}

TEST_F(ReferenceCurveTest, PchipIsCloseToLinearButNotIdentical) {
    const Material gold = material("Au");
    const RGB linear = curve(gold)(1.0);
    const RGB pchip =
        curve(gold, {}, Observer::cie1931_2deg, Illuminant::D65, {Interpolation::pchip, OutOfRange::error})(1.0);
    double largest = 0.0;
    for (int c = 0; c < 3; ++c) largest = std::max(largest, std::abs(linear[c] - pchip[c]));
    EXPECT_GT(largest, 1e-5);
    EXPECT_LT(largest, 0.02);
}

TEST_F(ReferenceCurveTest, AluminiumHasItsMinimumNearGrazing) {
    // Aluminium's reflectance is not monotone in μ: it dips below F0 before rising to 1 (Lazányi 2008, ch. 3; docs/references.md).
    const ReferenceCurve r = curve(material("Al"));
    const double f0 = r(1.0).g;
    double minimum = 1.0, at = 1.0;
    for (int i = 1; i < 100; ++i) {
        const double mu = i / 100.0, g = r(mu).g;
        if (g < minimum) minimum = g, at = mu;
    }
    EXPECT_LT(minimum, f0 - 0.02);
    EXPECT_LT(at, 0.4);
}

}  // namespace test_reference_curve
}  // namespace metalfit
