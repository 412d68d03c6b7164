// The renderers' thin-film approximations (optics/renderer_thin_film.hpp) and their scores
// (fit/renderer_film_scores.hpp): MaterialX against a second transcription of its published GLSL (MaterialX 1.39.4,
// libraries/pbrlib/genglsl/lib/mx_microfacet_specular.glsl) in long double; each approximation at d = 0 against the
// conductor's complex Fresnel (optics/fresnel.hpp); Belcour & Barla without a film interface; the three-wavelength
// Airy against an Airy sum written here from Born & Wolf's coefficients; the scores' plumbing at d = 0 against the
// conductor-rgb fit's own metrics.
#include <gtest/gtest.h>

#include "test_support.hpp"

#include <cmath>
#include <complex>
#include <numbers>
#include <random>

#include "libfit/fit/fit.hpp"
#include "libfit/fit/renderer_film_scores.hpp"
#include "libfit/io/catalog.hpp"
#include "libfit/io/layer_materials.hpp"
#include "libfit/optics/fresnel.hpp"
#include "libfit/optics/renderer_thin_film.hpp"
#include "libfit/reference/stack_grid.hpp"

namespace metalfit {
namespace test_renderer_thin_film {
using test::kData;

using L = long double;
const L kPiL = 3.141592653589793238462643383279502884L;

// --- MaterialX 1.39.4's mx_fresnel_airy for a conductor, transcribed again (long double, one polarisation at a time).
L sq(L x) { return x * x; }

// mx_fresnel_dielectric_polarized → (Rp, Rs)
void dielectric_polarized(L c, L ior, L& Rp, L& Rs) {
    const L c2 = sq(std::clamp(c, L(0), L(1))), s2 = 1 - c2;
    const L t0 = std::max(ior * ior - s2, L(0)), t1 = t0 + c2, t2 = 2 * std::sqrt(t0) * c;
    Rs = (t1 - t2) / (t1 + t2);
    const L t3 = c2 * t0 + s2 * s2, t4 = t2 * s2;
    Rp = Rs * (t3 - t4) / (t3 + t4);
}
void conductor_polarized(L c, L n, L k, L& Rp, L& Rs) {
    const L c2 = sq(std::clamp(c, L(0), L(1))), s2 = 1 - c2;
    const L t0 = n * n - k * k - s2, ab = std::sqrt(t0 * t0 + 4 * n * n * k * k), t1 = ab + c2;
    const L a = std::sqrt(std::max(L(0.5) * (ab + t0), L(0))), t2 = 2 * a * c;
    Rs = (t1 - t2) / (t1 + t2);
    const L t3 = c2 * ab + s2 * s2, t4 = t2 * s2;
    Rp = Rs * (t3 - t4) / (t3 + t4);
}
void conductor_phase(L c, L eta1, L eta2, L kappa2, L& phiP, L& phiS) {
    const L k2 = kappa2 / eta2, s2 = 1 - c * c;
    const L A = eta2 * eta2 * (1 - k2 * k2) - eta1 * eta1 * s2, B = std::sqrt(A * A + sq(2 * eta2 * eta2 * k2));
    const L U = std::sqrt((A + B) / 2), V = std::max(L(0), std::sqrt((B - A) / 2));
    phiS = std::atan2(2 * eta1 * V * c, U * U + V * V - sq(eta1 * c));
    phiP = std::atan2(2 * eta1 * eta2 * eta2 * c * (2 * k2 * U - (1 - k2 * k2) * V),
                      sq(eta2 * eta2 * (1 + k2 * k2) * c) - eta1 * eta1 * (U * U + V * V));
}
// mx_eval_sensitivity, component i
L sensitivity(L opd, L shift, int i) {
    const L phase = 2 * kPiL * opd;
    const L val[3] = {5.4856e-13L, 4.4201e-13L, 5.2481e-13L}, pos[3] = {1.6810e+06L, 1.7953e+06L, 2.2084e+06L},
            var[3] = {4.3278e+09L, 9.3046e+09L, 6.6121e+09L};
    L v = val[i] * std::sqrt(2 * kPiL * var[i]) * std::cos(pos[i] * phase + shift) * std::exp(-var[i] * phase * phase);
    if (i == 0)
        v += 9.7470e-14L * std::sqrt(2 * kPiL * 4.5282e+09L) * std::cos(2.2399e+06L * phase + shift) *
             std::exp(-4.5282e+09L * phase * phase);
    return v / 1.0685e-7L;
}
std::array<L, 3> materialx_glsl(L cosTheta, const ChannelIndices& metal, L tf_ior, L tf_thickness) {
    const L M[3][3] = {{2.3706743L, -0.9000405L, -0.4706338L},  // mat3's columns, read as rows of the product
                       {-0.5138850L, 1.4253036L, 0.0885814L},
                       {0.0052982L, -0.0146949L, 1.0093968L}};
    const L eta1 = 1, eta2 = std::max(tf_ior, eta1);
    const L cosThetaT = std::sqrt(1 - (1 - sq(cosTheta)) * sq(eta1 / eta2));
    L R12[2];  // p, s
    dielectric_polarized(cosTheta, eta2 / eta1, R12[0], R12[1]);
    if (cosThetaT <= 0) R12[0] = R12[1] = 1;
    const L cosB = std::cos(std::atan(eta2 / eta1));
    const L phi21[2] = {cosTheta < cosB ? L(0) : kPiL, kPiL};
    const L opd = 2 * eta2 * cosThetaT * (tf_thickness * 1.0e-9L);
    L I[3] = {0, 0, 0};
    for (int c = 0; c < 3; ++c) {
        const L eta3 = metal[c].real(), kappa3 = metal[c].imag();
        L R23[2], phi23[2];
        conductor_polarized(cosThetaT, eta3 / eta2, kappa3 / eta2, R23[0], R23[1]);
        conductor_phase(cosThetaT, eta2, eta3, kappa3, phi23[0], phi23[1]);
        for (int pol = 0; pol < 2; ++pol) {
            const L T121 = 1 - R12[pol], r123 = std::max(std::sqrt(R12[pol] * R23[pol]), L(0));
            const L Rs = sq(T121) * R23[pol] / (1 - R12[pol] * R23[pol]);
            L Cm = Rs - T121, sum = R12[pol] + Rs;
            for (int m = 1; m <= 2; ++m) {
                Cm *= r123;
                sum += Cm * 2 * sensitivity(m * opd, m * (phi23[pol] + phi21[pol]), c);
            }
            I[c] += sum / 2;
        }
    }
    std::array<L, 3> rgb{};
    for (int i = 0; i < 3; ++i) rgb[i] = std::clamp(M[i][0] * I[0] + M[i][1] * I[1] + M[i][2] * I[2], L(0), L(1));
    return rgb;
}

ChannelIndices random_metal(std::mt19937_64& rng) {
    std::uniform_real_distribution<double> n(0.05, 3.5), k(0.5, 8.0);
    return {std::complex<double>(n(rng), k(rng)), {n(rng), k(rng)}, {n(rng), k(rng)}};
}

TEST(RendererThinFilm, MaterialxIsItsPublishedGlslRecomputedInLongDouble) {
    std::mt19937_64 rng(28);
    std::uniform_real_distribution<double> mu(0.0, 1.0), ior(1.0, 3.0), d(0.5, 1500.0);
    double worst = 0;
    for (int i = 0; i < 20000; ++i) {
        const ChannelIndices metal = random_metal(rng);
        const double m = i % 100 == 0 ? 1.0 : mu(rng), n = ior(rng), t = d(rng);
        const ChannelReflectance got = materialx_thin_film(m, metal, n, t);
        const std::array<L, 3> want = materialx_glsl(m, metal, n, t);
        for (int c = 0; c < 3; ++c) worst = std::max(worst, static_cast<double>(std::abs(got[c] - want[c])));
    }
    std::cout << "[ MaterialX ] largest |double - long double| over 20000 random films: " << worst << "\n";
    EXPECT_LT(worst, 1e-12);
}

// The one phase convention: MaterialX's phases of the film → metal reflection are those of the complex coefficients
// (optics/stack_reflectance.hpp's r_s, r_p): φ_s = arg(r_s) + π, φ_p = arg(r_p) (mod 2π), so that its round trip,
// φ21 + φ23, is the exact arg(r10 r12).
TEST(RendererThinFilm, MaterialxPhasesAreThoseOfTheComplexCoefficients) {
    std::mt19937_64 rng(82);
    std::uniform_real_distribution<double> mu(0.01, 1.0), ior(1.05, 3.0);
    for (int i = 0; i < 2000; ++i) {
        const std::complex<double> eta = random_metal(rng)[0];
        const double n1 = ior(rng), mu_air = mu(rng), sin2 = 1 - mu_air * mu_air;
        const double cos_f = std::sqrt(1 - sin2 / (n1 * n1));
        const std::complex<double> u1 = n1 * cos_f, um = std::sqrt(eta * eta - sin2);
        const std::complex<double> rs = (u1 - um) / (u1 + um),
                                   rp = (eta * eta * u1 - n1 * n1 * um) / (eta * eta * u1 + n1 * n1 * um);
        L phiP, phiS;
        conductor_phase(cos_f, n1, eta.real(), eta.imag(), phiP, phiS);
        const auto same_angle = [](double a, double b) {
            return std::abs(std::remainder(a - b, 2 * std::numbers::pi));
        };
        EXPECT_LT(same_angle(static_cast<double>(phiS), std::arg(rs) + std::numbers::pi), 1e-9);
        EXPECT_LT(same_angle(static_cast<double>(phiP), std::arg(rp)), 1e-9);
        // The round trip: MaterialX's φ21 (s: π; p: 0 below Brewster's angle, π above) plus φ23, against the exact
        // arg(r10 r12) = arg(−r01) + arg(r12), r01 from air into the film.
        const double u0 = mu_air;
        const double r01s = (u0 - n1 * cos_f) / (u0 + n1 * cos_f),
                     r01p = (n1 * n1 * u0 - n1 * cos_f) / (n1 * n1 * u0 + n1 * cos_f);
        const double phi21p = mu_air < std::cos(std::atan(n1)) ? 0.0 : std::numbers::pi, phi21s = std::numbers::pi;
        EXPECT_LT(same_angle(phi21s + static_cast<double>(phiS), std::arg(std::complex<double>(-r01s)) + std::arg(rs)),
                  1e-9);
        EXPECT_LT(same_angle(phi21p + static_cast<double>(phiP), std::arg(std::complex<double>(-r01p)) + std::arg(rp)),
                  1e-9);
    }
}

// (M · S(0))_c: what Belcour & Barla's DC weighting and CIE RGB make of a flat spectrum.
std::array<double, 3> flat_gain() {
    const std::array<double, 3> s0 = thin_film_sensitivity(0.0, {0, 0, 0});
    std::array<double, 3> g{};
    for (int i = 0; i < 3; ++i)
        for (int j = 0; j < 3; ++j) g[i] += kXyzToCie1931Rgb[i][j] * s0[j];
    return g;
}

TEST(RendererThinFilm, AtZeroThicknessEachIsItsBareConductorFresnel) {
    std::mt19937_64 rng(7);
    std::uniform_real_distribution<double> mu(0.0, 1.0), ior(1.0, 3.0);
    const std::array<double, 3> gain = flat_gain();
    for (double g : gain) EXPECT_NEAR(g, 1.0, 2e-3);  // the Gaussian fits' normalisation
    for (int i = 0; i < 5000; ++i) {
        const ChannelIndices metal = random_metal(rng);
        const double m = i == 0 ? 0.0 : (i == 1 ? 1.0 : mu(rng)), n = ior(rng);
        const ChannelReflectance mx = materialx_thin_film(m, metal, n, 0.0);
        const ChannelReflectance bb = belcour_barla_thin_film(m, metal, n, 0.0);
        std::array<StackOptics<double>, 3> optics;
        for (int c = 0; c < 3; ++c) {
            optics[c].metal = metal[c];
            optics[c].has_film = true;
            optics[c].film = {n, 0.01};
            optics[c].film_thickness_per_wavelength = 0.0;
        }
        const ChannelReflectance airy = three_wavelength_airy(m, optics);
        for (int c = 0; c < 3; ++c) {
            const double bare = fresnel(m, metal[c]);
            EXPECT_NEAR(mx[c], bare, 1e-12) << m;
            EXPECT_NEAR(bb[c], std::min(1.0, bare * gain[c]), 1e-12) << m;
            EXPECT_NEAR(airy[c], bare, 1e-12) << m;
        }
    }
}

// A film of index 1 has no interface of its own: Belcour & Barla's series is its DC term alone at any thickness.
TEST(RendererThinFilm, BelcourBarlaWithoutAFilmInterfaceIsTheBareConductorAtAnyThickness) {
    std::mt19937_64 rng(11);
    std::uniform_real_distribution<double> mu(0.0, 1.0), d(0.0, 2000.0);
    const std::array<double, 3> gain = flat_gain();
    for (int i = 0; i < 2000; ++i) {
        const ChannelIndices metal = random_metal(rng);
        const double m = mu(rng);
        const ChannelReflectance bb = belcour_barla_thin_film(m, metal, 1.0, d(rng));
        for (int c = 0; c < 3; ++c) EXPECT_NEAR(bb[c], std::min(1.0, fresnel(m, metal[c]) * gain[c]), 1e-12);
    }
}

// Airy's sum with Born & Wolf's coefficients written as cosines (θ in each medium), in long double.
L airy_born_wolf(L mu, std::complex<L> film, L d_nm, std::complex<L> metal, L lambda_nm) {
    using CL = std::complex<L>;
    const L sin2 = 1 - mu * mu;
    const CL c1 = std::sqrt(L(1) - sin2 / (film * film)), c2 = std::sqrt(L(1) - sin2 / (metal * metal));
    const CL beta = 2 * kPiL / lambda_nm * film * d_nm * c1;
    const auto airy = [&](CL r01, CL r12) {
        const CL e = std::exp(CL(0, 2) * beta);
        return std::norm((r01 + r12 * e) / (L(1) + r01 * r12 * e));
    };
    const CL rs01 = (mu - film * c1) / (mu + film * c1), rs12 = (film * c1 - metal * c2) / (film * c1 + metal * c2);
    const CL rp01 = (film * mu - c1) / (film * mu + c1), rp12 = (metal * c1 - film * c2) / (metal * c1 + film * c2);
    return (airy(rs01, rs12) + airy(rp01, rp12)) / 2;
}

struct Data {
    Catalog catalog = Catalog::load(kData);
    FilmCatalog films = FilmCatalog::load(kData);
    Colorimetry colorimetry = Colorimetry::load(kData, Observer::cie1931_2deg, Illuminant::D65);
    ColorSpaceConverter converter =
        ColorSpaceConverter::create(OcioConfigChoice{kData / "ocio" / "config.ocio", "test"});
};
const Data& data() {
    static const Data d;
    return d;
}

TEST(RendererThinFilm, ThreeWavelengthAiryIsTheExactAiryAtItsWavelengths) {
    Material ti = load_material(data().catalog, "Ti");
    const LayerMaterial tio2 = load_film_material(data().films, "TiO2");
    for (const double d : {0.0, 35.0, 80.0, 160.0, 290.0}) {
        auto stack = std::make_shared<LayerStack>();
        stack->film = ThinFilm{tio2, d};
        ti.layers = stack;
        std::array<StackOptics<double>, 3> optics;
        for (int c = 0; c < 3; ++c) {
            const int nm = static_cast<int>(kThreeWavelengthsNm[c]);
            optics[c] = stack_optics_on_grid(ti, nm, nm, {}).front();
        }
        for (const double mu : {1.0, 0.8, 0.5, 1.0 / 7.0, 0.02}) {
            const ChannelReflectance got = three_wavelength_airy(mu, optics);
            for (int c = 0; c < 3; ++c) {
                const L lambda = kThreeWavelengthsNm[c];
                const std::complex<double> m = ti.index(lambda), f = tio2.index(lambda);
                const L want = airy_born_wolf(mu, {f.real(), f.imag()}, d, {m.real(), m.imag()}, lambda);
                EXPECT_NEAR(got[c], static_cast<double>(want), 1e-12) << d << " nm, μ " << mu << ", channel " << c;
            }
        }
    }
}

// At d = 0 MaterialX draws its bare conductor with the conductor-rgb fit's n, k: its scores are that fit's metrics.
// And the truth scored against itself is exact.
TEST(RendererFilmScores, AtZeroThicknessMaterialxScoresAsTheConductorRgbFit) {
    const Material ti = load_material(data().catalog, "Ti");
    const LayerMaterial tio2 = load_film_material(data().films, "TiO2");
    const RendererFilmScores scores =
        renderer_film_scores({ti, tio2, {0.0, 80.0}, ErrorSettings{}}, data().colorimetry, data().converter, {});
    ASSERT_EQ(scores.rows.size(), 2u);
    EXPECT_NEAR(scores.constants.film_ior, tio2.index(550.0).real(), 1e-12);

    const ReferenceCurve bare(ti, data().colorimetry, data().converter, {});
    const SampledReference reference(bare, ErrorSettings{});
    const Model& conductor = find_model("conductor-rgb");
    const ModelParameters params({scores.constants.metal[0].real(), scores.constants.metal[0].imag()},
                                 {scores.constants.metal[1].real(), scores.constants.metal[1].imag()},
                                 {scores.constants.metal[2].real(), scores.constants.metal[2].imag()});
    const Metrics want = compute_metrics(conductor, params, reference);
    const Metrics& got = scores.rows[0].scores[0].metrics;
    ASSERT_EQ(scores.rows[0].scores[0].renderer, FilmRenderer::materialx);
    for (int c = 0; c < 3; ++c) {
        EXPECT_NEAR(got.rel_rms[c], want.rel_rms[c], 1e-12);
        EXPECT_NEAR(got.err_f0[c], want.err_f0[c], 1e-12);
    }
    EXPECT_NEAR(got.de2000_mean, want.de2000_mean, 1e-10);
    // The fit is the best conductor-rgb: a good one (docs/fitting.md's conductor-rgb on Ti is well under 1 %).
    EXPECT_LT(worst_channel(got.rel_rms), 0.01);

    const Metrics self = curve_metrics([&](double mu) { return bare(mu); }, reference);
    for (int c = 0; c < 3; ++c) EXPECT_EQ(self.rel_rms[c], 0.0);
    EXPECT_LT(self.de2000_max, 1e-9);
    // The working space's matrix is the converter's, each row balanced so that XYZ (1, 1, 1) is white.
    const RGB white = data().converter(XYZ{1, 1, 1});
    for (const XYZ xyz : {XYZ{0.3, 0.5, 0.2}, XYZ{0.9, 0.1, 0.4}}) {
        const RGB want_rgb = data().converter(xyz);
        const XyzToRgbMatrix& m = scores.constants.xyz_to_working;
        for (int i = 0; i < 3; ++i)
            EXPECT_NEAR(m[i][0] * xyz.X + m[i][1] * xyz.Y + m[i][2] * xyz.Z, want_rgb[i] / white[i], 1e-6);
    }
    ASSERT_EQ(scores.rows[0].scores[3].renderer, FilmRenderer::belcour_barla_working);
    // At d = 0 it is the conductor-rgb metal times its sensitivities' normalisation in that space: within 2e-3.
    for (double e : scores.rows[0].scores[3].metrics.err_f0) EXPECT_LT(std::abs(e), 2e-3);
    // MaterialX given the measured n, k at 650, 550, 450 nm draws at d = 0 the bare Fresnel of those indices, which
    // is airy-3's at d = 0 (computed by the stack kernel): the same scores.
    ASSERT_EQ(scores.rows[0].scores[1].renderer, FilmRenderer::materialx_nk);
    ASSERT_EQ(scores.rows[0].scores[4].renderer, FilmRenderer::three_wavelength);
    for (int c = 0; c < 3; ++c) {
        EXPECT_NEAR(scores.constants.metal_at_wavelengths[c].real(), ti.index(kThreeWavelengthsNm[c]).real(), 0);
        EXPECT_NEAR(scores.rows[0].scores[1].metrics.rel_rms[c], scores.rows[0].scores[4].metrics.rel_rms[c], 1e-12);
    }
    EXPECT_NEAR(scores.rows[0].scores[1].metrics.de2000_mean, scores.rows[0].scores[4].metrics.de2000_mean, 1e-10);
    // Under a film the approximations are not the truth.
    for (const RendererScore& s : scores.rows[1].scores) EXPECT_GT(s.metrics.de2000_mean, 0.1);
}

}  // namespace test_renderer_thin_film
}  // namespace metalfit
