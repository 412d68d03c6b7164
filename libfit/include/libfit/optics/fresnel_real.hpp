// The exact conductor Fresnel in real arithmetic: per wavelength (or per channel) the constants of η² = n² − k² +
// i 2nk are computed once (SquaredIndex), per angle only real operations remain, without branches, calls or errno
// (a source using it over arrays is built with -fno-math-errno so that the square roots vectorise). It gives the
// complex form of fresnel.hpp (the independent check, tests/test_fresnel_real.cpp) to rounding.
//
// With z = η² − sin²θ = η² cos²θ_t and u = η cos θ_t = a + i b (the root with a ≥ 0), r_s = (μ − u)/(μ + u) and
// r_p = (η² μ − u)/(η² μ + u) (r_p of fresnel.hpp multiplied through by η), so
//   |r_s|² = (|z| − 2aμ + μ²) / (|z| + 2aμ + μ²),
//   |r_p|² = (|η²|² μ² − 2μ (Re η² a + Im η² b) + |z|) / (|η²|² μ² + 2μ (…) + |z|).
// Re z = (Re η² − 1) + μ² (no cancellation near grazing). a and b come from the cancellation-free root: p = sqrt((|z| + |Re z|)/2), q = |Im z| / 2p; a = p, b = q when
// Re z ≥ 0, else a = q, b = p (so a dielectric under total internal reflection, Im z = 0, gives exactly 1).
#pragma once

#include <cmath>
#include <complex>
#include <limits>

namespace metalfit {

// η² of one wavelength: its real part, Re η² − 1 (so that z = η² − sin²θ has Re z = (Re η² − 1) + μ², without the
// cancellation of 1 − μ² near grazing, and η = 1 gives exactly 0), the magnitude of its imaginary part and |η²|².
template <class T>
struct SquaredIndex {
    T re{}, re_minus_1{}, im{}, norm2{};
};

template <class T = double>
SquaredIndex<T> squared_index(std::complex<double> eta) {
    const double n = eta.real(), k = eta.imag();
    const double re = (n - k) * (n + k), im = std::abs(2.0 * n * k);
    return {T(re), T((n - 1.0) * (n + 1.0) - k * k), T(im), T(re * re + im * im)};
}

namespace fresnel_real_detail {
// By value (std::min/max return references, which keep the compiler from if-converting the loop).
template <class T>
inline T min_of(T a, T b) {
    return b < a ? b : a;
}  // a when NaN
template <class T>
inline T max_of(T a, T b) {
    return a < b ? b : a;
}
}  // namespace fresnel_real_detail

// Unpolarised reflectance (|r_s|² + |r_p|²)/2 at μ (clamped to [0, 1]) of the index whose η² is given as SquaredIndex;
// F(0) = 1 for η ≠ 1 and η = 1 reflects nothing. Branch-free: the selects compile to blends.
template <class T>
inline T fresnel_real(T mu, T re, T re_minus_1, T im, T norm2) {
    using fresnel_real_detail::max_of;
    using fresnel_real_detail::min_of;
    constexpr T tiny = std::numeric_limits<T>::min();
    mu = min_of(max_of(mu, T(0)), T(1));
    const T mu2 = mu * mu;
    const T zr = re_minus_1 + mu2;  // Re η² − (1 − μ²)
    const T zabs = std::sqrt(zr * zr + im * im);
    const T p = std::sqrt(T(0.5) * (zabs + std::abs(zr)));
    const T q = im / (T(2) * max_of(p, tiny));
    const bool real_part_positive = zr >= T(0);
    const T a = real_part_positive ? p : q;
    const T b = real_part_positive ? q : p;
    const T two_a_mu = T(2) * a * mu;
    const T fs = (zabs - two_a_mu + mu2) / max_of(zabs + two_a_mu + mu2, tiny);
    const T c = T(2) * mu * (re * a + im * b);
    const T fp = (norm2 * mu2 - c + zabs) / max_of(norm2 * mu2 + c + zabs, tiny);
    // |r|² can round to 1 + ulp under total internal reflection (as in the complex form).
    return T(0.5) * (min_of(fs, T(1)) + min_of(fp, T(1)));
}

template <class T>
inline T fresnel_real(T mu, const SquaredIndex<T>& e) {
    return fresnel_real(mu, e.re, e.re_minus_1, e.im, e.norm2);
}

}  // namespace metalfit
