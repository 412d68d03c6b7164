// The reflectance of a layered metal at one wavelength: a metal, optionally under a thin film (coherent: Airy
// summation of the amplitudes per polarisation) and optionally under a smooth dielectric coat (incoherent: the
// intensities of the inner reflections summed per polarisation, with absorption over the path). Formulas and sources:
// docs/colour.md, "Layered metals".
//
// Every layer is described by u_j = η_j cos θ_j = sqrt(η_j² − sin²θ), θ in air (Snell's invariant: the ambient is
// air, n = 1), on the branch with Im u ≥ 0 (a wave that decays downwards; a non-absorbing layer under total internal
// reflection gets u = i|u|). With it, the amplitude reflection coefficients of the interface j → k are
//   r_s = (u_j − u_k) / (u_j + u_k),    r_p = (η_k² u_j − η_j² u_k) / (η_k² u_j + η_j² u_k)
// (r_p of optics/fresnel.hpp for j = air), two equal media (u_j = u_k = 0 at grazing incidence included) reflect
// nothing, and the film's round-trip phase is 2β = 2π · 2 d u_f / λ = 4π n_f d cos θ_f / λ.
#pragma once

#include <algorithm>
#include <cmath>
#include <complex>
#include <limits>

namespace metalfit {

// The optical constants of a stack at one wavelength λ, in the form the kernel uses.
template <class T>
struct StackOptics {
    std::complex<T> metal{1, 0};  // η = n + ik of the substrate
    bool has_film = false;
    std::complex<T> film{1, 0};           // η_f = n_f + i k_f
    T film_thickness_per_wavelength = 0;  // d / λ (both in nm)
    bool has_coat = false;
    T coat_index = 1;       // n_c ≥ 1, real: the coat's interfaces are those of a clear dielectric
    T coat_absorbance = 0;  // 4π k_c d_c / λ: −ln of the intensity transmitted by one pass at normal incidence
};

template <class T>
struct StackReflectance {
    T s = 0;  // perpendicular (TE) polarisation
    T p = 0;  // parallel (TM) polarisation
    T unpolarized() const { return T(0.5) * (s + p); }
};

namespace stack_detail {

// u = sqrt(η² − sin²θ) with η² − sin²θ = (η² − 1) + μ² and Re η² − 1 = (n − 1)(n + 1) − k²: no cancellation near
// grazing incidence for an index near 1 (as in optics/fresnel_real.hpp).
template <class T>
std::complex<T> normal_component(std::complex<T> eta, T mu2) {
    const T n = eta.real(), k = eta.imag();
    std::complex<T> u = std::sqrt(std::complex<T>((n - T(1)) * (n + T(1)) - k * k + mu2, T(2) * n * k));
    if (u.imag() < T(0) || (u.imag() == T(0) && u.real() < T(0))) u = -u;
    return u;
}

template <class T>
std::complex<T> quotient_or_zero(std::complex<T> num, std::complex<T> den) {
    return den == std::complex<T>(0, 0) ? std::complex<T>(0, 0) : num / den;
}

template <class T>
T clamp_unit(T r) {  // |r|² can round to 1 + ulp; the comparisons keep NaN visible
    return r > T(1) ? T(1) : (r < T(0) ? T(0) : r);
}

// Amplitude reflection coefficients, s and p, of what lies below a medium of index η_top (u_top), down to the metal:
// the metal alone, or the film over it (Airy's sum of the film's multiple reflections).
template <class T>
void amplitude_below(const StackOptics<T>& o, std::complex<T> eta_top2, std::complex<T> u_top, T mu2,
                     std::complex<T>& r_s, std::complex<T>& r_p) {
    const std::complex<T> eta_m2 = o.metal * o.metal, u_m = normal_component(o.metal, mu2);
    if (!o.has_film) {
        r_s = quotient_or_zero(u_top - u_m, u_top + u_m);
        r_p = quotient_or_zero(eta_m2 * u_top - eta_top2 * u_m, eta_m2 * u_top + eta_top2 * u_m);
        return;
    }
    const std::complex<T> eta_f2 = o.film * o.film, u_f = normal_component(o.film, mu2);
    const std::complex<T> r01_s = quotient_or_zero(u_top - u_f, u_top + u_f);
    const std::complex<T> r12_s = quotient_or_zero(u_f - u_m, u_f + u_m);
    const std::complex<T> r01_p = quotient_or_zero(eta_f2 * u_top - eta_top2 * u_f, eta_f2 * u_top + eta_top2 * u_f);
    const std::complex<T> r12_p = quotient_or_zero(eta_m2 * u_f - eta_f2 * u_m, eta_m2 * u_f + eta_f2 * u_m);
    // e^{2iβ}, 2β = 4π (d/λ) u_f; Im u_f ≥ 0, so |e^{2iβ}| ≤ 1 however thick or absorbing the film.
    const T two_pi = T(2) * T(3.141592653589793238462643383279502884L);
    const std::complex<T> phase = std::exp(std::complex<T>(0, 2 * two_pi * o.film_thickness_per_wavelength) * u_f);
    r_s = (r01_s + r12_s * phase) / (T(1) + r01_s * r12_s * phase);
    r_p = (r01_p + r12_p * phase) / (T(1) + r01_p * r12_p * phase);
}

}  // namespace stack_detail

// Reflectance of the stack per polarisation at μ = cos θ in air (clamped to [0, 1]). R(0) = 1 for any stack whose top
// index differs from air's; every value lies in [0, 1].
template <class T>
StackReflectance<T> stack_reflectance(T mu, const StackOptics<T>& o) {
    using namespace stack_detail;
    using C = std::complex<T>;
    mu = std::clamp(mu, T(0), T(1));
    const T mu2 = mu * mu;
    if (!o.has_coat) {
        C r_s, r_p;
        amplitude_below(o, C(1, 0), C(mu, 0), mu2, r_s, r_p);
        return {clamp_unit(std::norm(r_s)), clamp_unit(std::norm(r_p))};
    }
    // The coat: air → coat interface (real indices, so its reflectances are equal from both sides and T = 1 − R),
    // then the incoherent sum of the light bouncing between it and what lies below, attenuated by τ² per round trip:
    //   R = R_01 + T_01² τ² R_b / (1 − R_01 τ² R_b),   τ = exp(−absorbance / cos θ_c)   (per polarisation).
    const T n_c = o.coat_index, n_c2 = n_c * n_c;
    const C u_c = normal_component(C(n_c, 0), mu2);
    const T r01_s = clamp_unit(std::norm(quotient_or_zero(C(mu, 0) - u_c, C(mu, 0) + u_c)));
    const T r01_p = clamp_unit(std::norm(quotient_or_zero(n_c2 * C(mu, 0) - u_c, n_c2 * C(mu, 0) + u_c)));
    C rb_s, rb_p;
    amplitude_below(o, C(n_c2, 0), u_c, mu2, rb_s, rb_p);
    // Path length per pass d / cos θ_c = d n_c / u_c; at u_c = 0 (n_c = 1 at grazing incidence) nothing passes.
    T tau2 = T(1);
    if (o.coat_absorbance > T(0))
        tau2 = u_c.real() > T(0) ? std::exp(-T(2) * o.coat_absorbance * n_c / u_c.real()) : T(0);
    const auto incoherent = [tau2](T r01, T rb) {
        const T t01 = T(1) - r01, x = tau2 * clamp_unit(rb);
        const T denominator = T(1) - r01 * x;
        const T inner = denominator > T(0) ? t01 * t01 * x / denominator : T(0);
        return clamp_unit(r01 + inner);
    };
    return {incoherent(r01_s, std::norm(rb_s)), incoherent(r01_p, std::norm(rb_p))};
}

// Unpolarised reflectance, (R_s + R_p) / 2.
template <class T>
T stack_reflectance_unpolarized(T mu, const StackOptics<T>& o) {
    return stack_reflectance(mu, o).unpolarized();
}

}  // namespace metalfit
