// The layered-metal kernel (optics/stack_reflectance.hpp) against an independent computation written here:
// characteristic (transfer) matrices per layer and polarisation for the coherent part (Born & Wolf, "Principles of
// Optics", §1.6), and intensity transfer matrices for the incoherent coat (Katsidis & Siapkas, "General
// transfer-matrix method for optical multilayer systems with coherent, partially coherent, and incoherent
// interference", Appl. Opt. 41, 3978 (2002)), with the interface's T_ab T_ba from Stokes' relation instead of 1 − R.
// Then the limits: no film, a coat of index 1, a quarter-wave film, energy.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <complex>
#include <iostream>
#include <numbers>
#include <random>
#include <vector>

#include "libfit/optics/fresnel.hpp"
#include "libfit/optics/stack_reflectance.hpp"

namespace metalfit {
namespace test_stack_reflectance {

using C = std::complex<double>;

struct Layer {
    C eta;
    double thickness_nm = 0;
};

enum class Pol { s, p };

// The reference works in long double (64-bit significand): near grazing incidence its Stokes form 1 − r² cancels
// where the kernel's 1 − R does not in the same way, and the comparison is to be about the kernel's digits.
using L = long double;
using CL = std::complex<long double>;
const L kPi = 3.141592653589793238462643383279502884L;

// The angle of the light in air, given as μ = cos θ and sin²θ = (1 − μ)(1 + μ) (recovering one from the other would
// lose the digits of μ near grazing incidence).
struct AirAngle {
    L mu, sin2;
};

// cos θ_j in a medium η_j (Snell: η_j sin θ_j = sin θ in air), chosen so that the wave η_j cos θ_j decays downwards
// (Im ≥ 0); air's own is μ.
CL cos_in(CL eta, AirAngle a) {
    if (eta == CL(1, 0)) return a.mu;
    const CL c = std::sqrt(L(1) - a.sin2 / (eta * eta));
    const CL u = eta * c;
    return (u.imag() < 0 || (u.imag() == 0 && u.real() < 0)) ? -c : c;
}

// Born & Wolf's pseudo-admittance: s: η cos θ; p: cos θ / η.
CL admittance(CL eta, CL cos_theta, Pol pol) { return pol == Pol::s ? eta * cos_theta : cos_theta / eta; }

// Amplitude reflection coefficient of the films on a substrate, seen from the medium n0: the product of the layers'
// characteristic matrices [[cos δ, −i sin δ / q], [−i q sin δ, cos δ]], δ = 2π η d cos θ / λ.
CL tmm_reflection(L n0, AirAngle a, const std::vector<Layer>& films, CL substrate, L lambda_nm, Pol pol) {
    if (films.empty() && substrate == CL(n0, 0)) return 0;  // no interface (0/0 below at grazing incidence)
    const CL q0 = admittance(CL(n0, 0), cos_in(CL(n0, 0), a), pol);
    CL m11 = 1, m12 = 0, m21 = 0, m22 = 1;
    for (const Layer& layer : films) {
        const CL eta(layer.eta.real(), layer.eta.imag());
        const CL c = cos_in(eta, a), q = admittance(eta, c, pol);
        const CL delta = L(2) * kPi * eta * L(layer.thickness_nm) * c / lambda_nm;
        const CL i(0, 1);
        const CL a11 = std::cos(delta), a12 = -i * std::sin(delta) / q, a21 = -i * q * std::sin(delta),
                 a22 = std::cos(delta);
        const CL n11 = m11 * a11 + m12 * a21, n12 = m11 * a12 + m12 * a22, n21 = m21 * a11 + m22 * a21,
                 n22 = m21 * a12 + m22 * a22;
        m11 = n11, m12 = n12, m21 = n21, m22 = n22;
    }
    const CL qs = admittance(substrate, cos_in(substrate, a), pol);
    const CL b = m11 + m12 * qs, c = m21 + m22 * qs;
    return (q0 * b - c) / (q0 * b + c);
}

struct Case {
    double lambda_nm = 550, mu = 1;
    C metal{0.2, 3.0};
    bool film = false;
    Layer film_layer;
    bool coat = false;
    double coat_n = 1.5, coat_k = 0, coat_thickness_nm = 0;
};

// The reference: TMM below the coat; the coat by intensity matrices I_ab = (1/T_ab) [[1, −R_ba], [R_ab, T_ab T_ba −
// R_ab R_ba]] and P = diag(1/τ, τ), R = M21 / M11 of M = I_air,coat · P · (column 1, R_below).
double reference(const Case& x, Pol pol) {
    std::vector<Layer> films;
    if (x.film) films.push_back(x.film_layer);
    const CL metal(x.metal.real(), x.metal.imag());
    const AirAngle a{x.mu, (1 - L(x.mu)) * (1 + L(x.mu))};
    if (!x.coat) return double(std::norm(tmm_reflection(1, a, films, metal, x.lambda_nm, pol)));
    const L n_c = x.coat_n;
    const L cos_c = cos_in(CL(n_c, 0), a).real();
    const L below = std::norm(tmm_reflection(n_c, a, films, metal, x.lambda_nm, pol));
    const CL r01 = tmm_reflection(1, a, {}, CL(n_c, 0), x.lambda_nm, pol);
    const CL r10 = tmm_reflection(n_c, a, {}, CL(1, 0), x.lambda_nm, pol);
    const L R01 = std::norm(r01), R10 = std::norm(r10);
    const L T01T10 = std::norm(L(1) - r01 * r01);  // Stokes: t_ab t_ba = 1 − r_ab², and the admittances cancel
    const L tau = cos_c > 0 ? std::exp(-4 * kPi * L(x.coat_k) * L(x.coat_thickness_nm) / (L(x.lambda_nm) * cos_c))
                            : (x.coat_k > 0 ? L(0) : L(1));
    if (tau == 0) return double(R01);
    // (I P v) with v = (1, R_below): first and second components (the common 1/T_ab cancels in the ratio).
    const L first = 1 / tau - R10 * tau * below, second = R01 / tau + (T01T10 - R01 * R10) * tau * below;
    return double(second / first);
}

StackOptics<double> optics_of(const Case& x) {
    StackOptics<double> o;
    o.metal = x.metal;
    o.has_film = x.film;
    o.film = x.film_layer.eta;
    o.film_thickness_per_wavelength = x.film_layer.thickness_nm / x.lambda_nm;
    o.has_coat = x.coat;
    o.coat_index = x.coat_n;
    o.coat_absorbance = 4.0 * std::numbers::pi * x.coat_k * x.coat_thickness_nm / x.lambda_nm;
    return o;
}

TEST(StackReflectance, MatchesIndependentTransferMatrices) {
    std::mt19937_64 random(20261202);
    auto uniform = [&](double a, double b) { return std::uniform_real_distribution<double>(a, b)(random); };
    const char* const kinds[] = {"bare metal", "film", "coat", "coat over film"};
    double worst[4] = {}, worst_mu[4] = {};
    int cases[4] = {};
    for (int i = 0; i < 40000; ++i) {
        const int kind = i % 4;
        Case x;
        x.lambda_nm = uniform(360, 830);
        const int which_mu = (i / 4) % 10;
        x.mu = which_mu == 0 ? 0.0 : which_mu == 1 ? 1.0 : which_mu == 2 ? 1e-6 : uniform(0, 1);
        // Metals (silver-like n ≈ 0.05 to chromium-like n ≈ 3) and, sometimes, a dielectric substrate.
        x.metal = (i % 17 == 0) ? C(uniform(1.3, 2.5), 0.0) : C(uniform(0.04, 4.0), uniform(0.5, 9.0));
        x.film = kind == 1 || kind == 3;
        if (x.film) {
            const double k = (i % 3 == 0) ? 0.0 : uniform(0.0, 0.6);  // clear and absorbing films (Fe2O3: k ≈ 0.1–0.6)
            x.film_layer = {C(uniform(1.0, 3.0), k), (i % 11 == 0) ? 0.0 : uniform(0.0, 2000.0)};
        }
        x.coat = kind >= 2;
        if (x.coat) {
            x.coat_n = (i % 13 == 0) ? 1.0 : uniform(1.0, 2.0);
            x.coat_k = (i % 2 == 0) ? 0.0 : uniform(0.0, 1e-3);
            x.coat_thickness_nm = uniform(0.0, 1e5);
        }
        const StackReflectance<double> r = stack_reflectance(x.mu, optics_of(x));
        for (Pol pol : {Pol::s, Pol::p}) {
            const double expected = reference(x, pol), got = pol == Pol::s ? r.s : r.p;
            ASSERT_TRUE(std::isfinite(got)) << kinds[kind] << " mu " << x.mu;
            const double d = std::abs(got - expected);
            if (d > worst[kind]) worst[kind] = d, worst_mu[kind] = x.mu;
            ASSERT_LE(d, 1e-9) << kinds[kind] << " λ " << x.lambda_nm << " mu " << x.mu << " metal " << x.metal
                               << " film " << x.film_layer.eta << " d " << x.film_layer.thickness_nm << " coat "
                               << x.coat_n << " k " << x.coat_k << " pol " << (pol == Pol::s ? "s" : "p") << ": " << got
                               << " vs " << expected;
        }
        ++cases[kind];
    }
    for (int kind = 0; kind < 4; ++kind)
        std::cout << "[ TMM      ] " << kinds[kind] << ": " << cases[kind] << " cases, max |ΔR| over s and p "
                  << worst[kind] << " (at μ = " << worst_mu[kind] << ")\n";
}

TEST(StackReflectance, ZeroThicknessFilmIsTheBareMetal) {
    for (double n : {0.05, 0.3, 1.2, 2.5})
        for (double k : {0.0, 0.8, 3.5, 8.0}) {
            if (k == 0.0 && n == 1.2) continue;
            StackOptics<double> o;
            o.metal = C(n, k);
            o.has_film = true;
            o.film = C(2.3, 0.05);
            o.film_thickness_per_wavelength = 0.0;
            for (double mu = 0.0; mu <= 1.0; mu += 1.0 / 64) {
                const FresnelReflectance bare = fresnel_reflectance(mu, C(n, k));
                const StackReflectance<double> r = stack_reflectance(mu, o);
                EXPECT_NEAR(r.s, bare.s, 1e-13) << n << " " << k << " " << mu;
                EXPECT_NEAR(r.p, bare.p, 1e-13) << n << " " << k << " " << mu;
                // Thinner and thinner films converge to it too.
                o.film_thickness_per_wavelength = 1e-9;
                EXPECT_NEAR(stack_reflectance_unpolarized(mu, o), bare.unpolarized(), 1e-7);
                o.film_thickness_per_wavelength = 0.0;
            }
        }
}

TEST(StackReflectance, CoatOfIndexOneWithoutAbsorptionIsTheBareMetal) {
    for (bool film : {false, true})
        for (double mu = 0.0; mu <= 1.0; mu += 1.0 / 128) {
            StackOptics<double> o;
            o.metal = C(0.18, 3.1);
            o.has_film = film;
            o.film = C(2.1, 0.02);
            o.film_thickness_per_wavelength = 0.2;
            StackOptics<double> coated = o;
            coated.has_coat = true;
            coated.coat_index = 1.0;
            EXPECT_NEAR(stack_reflectance_unpolarized(mu, coated), stack_reflectance_unpolarized(mu, o), 1e-12) << mu;
        }
}

// A non-absorbing film of index n_f and thickness d on a clear substrate n_s at normal incidence reflects
// R = ((n_s − n_f²) / (n_s + n_f²))² at λ = 4 n_f d: a minimum when n_f lies between 1 and n_s, a maximum when n_f
// is above n_s (Born & Wolf §1.6.4).
TEST(StackReflectance, QuarterWaveFilmHasItsExtremumWhereTheoryPutsIt) {
    struct Film {
        double n_f, n_s, d;
        bool minimum;
    };
    for (const Film f : {Film{1.38, 1.52, 100.0, true}, Film{1.23, 1.9, 120.0, true}, Film{2.3, 1.52, 60.0, false},
                         Film{2.6, 1.46, 70.0, false}}) {
        const double lambda0 = 4.0 * f.n_f * f.d;
        auto reflectance = [&](double lambda) {
            StackOptics<double> o;
            o.metal = C(f.n_s, 0.0);
            o.has_film = true;
            o.film = C(f.n_f, 0.0);
            o.film_thickness_per_wavelength = f.d / lambda;
            return stack_reflectance_unpolarized(1.0, o);
        };
        // The extremum on a 0.001 nm grid over ±20 % of λ0.
        double best_lambda = 0, best = f.minimum ? 2.0 : -1.0;
        for (double lambda = 0.8 * lambda0; lambda <= 1.2 * lambda0; lambda += 0.001) {
            const double r = reflectance(lambda);
            if (f.minimum ? r < best : r > best) best = r, best_lambda = lambda;
        }
        EXPECT_NEAR(best_lambda, lambda0, 0.002) << f.n_f << " on " << f.n_s;
        const double theory = std::pow((f.n_s - f.n_f * f.n_f) / (f.n_s + f.n_f * f.n_f), 2);
        EXPECT_NEAR(reflectance(lambda0), theory, 1e-14) << f.n_f << " on " << f.n_s;
        // Bare substrate for comparison: the film lowers (minimum) or raises (maximum) it.
        const double bare = std::pow((f.n_s - 1.0) / (f.n_s + 1.0), 2);
        if (f.minimum)
            EXPECT_LT(theory, bare);
        else
            EXPECT_GT(theory, bare);
    }
}

TEST(StackReflectance, StaysWithinZeroAndOneAndIsOneAtGrazingIncidence) {
    std::mt19937_64 random(7);
    auto uniform = [&](double a, double b) { return std::uniform_real_distribution<double>(a, b)(random); };
    for (int i = 0; i < 20000; ++i) {
        StackOptics<double> o;
        o.metal = C(uniform(0.01, 6.0), uniform(0.0, 12.0));
        o.has_film = i % 2 == 0;
        o.film = C(uniform(1.0, 3.5), uniform(0.0, 2.0));
        o.film_thickness_per_wavelength = uniform(0.0, 2000.0 / 360.0);
        o.has_coat = i % 3 != 0;
        o.coat_index = uniform(1.0, 2.5);
        o.coat_absorbance = i % 5 == 0 ? 0.0 : uniform(0.0, 3.0);
        const double mu = uniform(0.0, 1.0);
        const StackReflectance<double> r = stack_reflectance(mu, o);
        ASSERT_GE(r.s, 0.0);
        ASSERT_LE(r.s, 1.0);
        ASSERT_GE(r.p, 0.0);
        ASSERT_LE(r.p, 1.0);
        // Under a coat, never below the coat's own surface reflection (what comes back from below only adds to it).
        if (o.has_coat && o.coat_index > 1.0 + 1e-6) {
            StackOptics<double> surface;
            surface.metal = C(o.coat_index, 0.0);
            EXPECT_GE(r.unpolarized(), stack_reflectance_unpolarized(mu, surface) - 1e-15);
        }
        if (!(o.has_coat && o.coat_index == 1.0)) {
            EXPECT_DOUBLE_EQ(stack_reflectance_unpolarized(0.0, o), 1.0);
        }
    }
}

TEST(StackReflectance, ACoatOverAPerfectMirrorReflectsEverythingWithoutAbsorptionAndLessWithIt) {
    // R_b = 1 below a clear coat: everything comes back out (R = 1 at every angle); absorption takes some of it.
    StackOptics<double> o;
    o.metal = C(0.0, 1e6);  // |r| = 1 to 1e-12: a perfect conductor
    o.has_coat = true;
    o.coat_index = 1.5;
    for (double mu : {0.0, 0.1, 0.5, 1.0}) {
        EXPECT_NEAR(stack_reflectance_unpolarized(mu, o), 1.0, 1e-9) << mu;
        StackOptics<double> absorbing = o;
        absorbing.coat_absorbance = 0.1;
        if (mu > 0) {
            EXPECT_LT(stack_reflectance_unpolarized(mu, absorbing), 0.999) << mu;
        }
    }
}

}  // namespace test_stack_reflectance
}  // namespace metalfit
