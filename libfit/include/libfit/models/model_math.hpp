// Arithmetic shared by the model definitions, written once for double, float and Ceres Jets.
#pragma once

#include <cmath>
#include <limits>
#include <type_traits>

namespace metalfit::model_math {

// μ clamped into [0, 1]: every model evaluates its curve at the clamped μ, so that a cosine a hair outside [0, 1]
// (dot(N, V) = 1.0000001 is routine in shaders) gives the value at the end of the range, never NaN or F > 1 (the
// GLSL functions clamp the same way). NaN stays NaN.
template <class T>
T clamp_mu(const T& mu) {
    if (mu < T(0)) return T(0);
    if (mu > T(1)) return T(1);
    return mu;
}

// (1 − μ)^5, the Schlick weight, by multiplication (as the GLSL does).
template <class T>
T schlick_weight(const T& mu) {
    const T m = T(1) - mu;
    const T m2 = m * m;
    return m2 * m2 * m;
}

// √x that is 0 with a zero derivative at and below 0, so that Jets never see 1/(2√0). For float and double the same
// values without a branch (√ of x or of 0, selected before the root), so that a loop over it can vectorise.
template <class T>
T sqrt_or_zero(const T& x) {
    using std::sqrt;
    if constexpr (std::is_floating_point_v<T>) {
        return sqrt(x > T(0) ? x : T(0));
    } else {
        if (!(x > T(0))) return T(0);
        return sqrt(x);
    }
}

// The smallest normal number of float, or of double for double and Jets.
template <class T>
T smallest_normal() {
    if constexpr (std::is_same_v<T, float>)
        return std::numeric_limits<float>::min();
    else
        return T(std::numeric_limits<double>::min());
}

// √x of an x that is ≥ 0 by construction (a sum of squares): the plain root for float and double (nothing to
// select), sqrt_or_zero for Jets (so that x = 0 has a zero derivative, not 1/(2√0)).
template <class T>
T nonnegative_sqrt(const T& x) {
    using std::sqrt;
    if constexpr (std::is_floating_point_v<T>)
        return sqrt(x);
    else
        return sqrt_or_zero(x);
}

// Exact unpolarised Fresnel reflectance of η = n + i k from vacuum, in the thesis's real form (eq. 1.5–1.6)
// rearranged so that nothing is divided by μ and nothing cancels for large k: t = n² − k² − s², r = sqrt(t² + 4n²k²) =
// |η² − s²|, a = Re sqrt(η² − s²), s² = 1 − μ²,
//   F_s = (r − 2aμ + μ²) / (r + 2aμ + μ²),  F_p = F_s (μ²r − 2as²μ + s⁴) / (μ²r + 2as²μ + s⁴),  F = (F_s + F_p)/2.
// p = sqrt((r + |t|)/2) is a where t ≥ 0 and b = Im sqrt(η² − s²) where t < 0, and there a = nk / b (ab = nk), not
// sqrt((r + t)/2), which cancels for large k. With a = num/den, (num, den) = (p, 1) where t ≥ 0 and (nk, p) where
// t < 0, both ratios are multiplied through by den, and F_s + F_p has the common factor F_s, so one division is left:
//   N_s = den (r + μ²) − 2 num μ,  D_s = den (r + μ²) + 2 num μ,  D_p = den (μ²r + s⁴) + 2 num s² μ,
//   F = N_s · den (μ²r + s⁴) / (D_s D_p)   (= ½ N_s (D_p + N_p) / (D_s D_p), N_p = D_p − 4 num s² μ).
// t = (n² − k² − 1) + μ² (not n² − k² − s²: η = 1 gives t = μ² exactly, so N_s = 0 and F = 0 at every μ). Every
// factor is ≥ 0 and the products grow as k⁶ (t < 0: den ≈ k, r ≈ k²), as n⁴ where t ≥ 0: float holds them to
// k ≈ 2·10⁶ (the models' bounds stop at 10⁴), double far beyond. Where t < 0, den = p ≥ sqrt(|t|) > 0. k = 0 with
// t < 0 (a dielectric's total reflection) has num = 0 and gives exactly 1. At μ = 0, N_s = D_s and den Q = D_p, so
// F = 1 exactly (its derivatives exactly 0), except η = 1, where D_s D_p = 0: the denominator is held at the smallest
// normal number, which gives F = 0 there (no interface), without a select on μ.
// Takes k² (r uses 4n²k²) and nk (only where t < 0), so that Gulbrandsen's k² = 0 keeps its derivative.
//
// Branch-free: both sides of every case are computed and selected (blends for float and double, so that an array
// loop over it vectorises when built without errno, docs/fitting.md), the same values and Jet derivatives as taking
// one side. The GLSL function, line for line (conductor_rgb.glsl, metalfit_conductor_fresnel; the C++ export is that
// GLSL): mu2, s2, t, r, p; num and den selected on t ≥ 0; X = r + μ², Q = μ²r + s⁴; N_s, D_s, D_p, B and F (the
// GLSL writes |t| as max(t, −t) and holds B at 1e-30, a float that no GPU flushes to zero).
template <class T>
struct ConductorFresnelTerms {
    T mu2, s2, t, r, p;
    bool t_positive;
    T num, den, X, Q, two_num_mu, Ns, Ds, Dp, B;
    T value() const {  // F = N_s den Q / (D_s D_p), the denominator held at the smallest normal
        const T tiny = smallest_normal<T>();
        return Ns * (den * Q) / (B > tiny ? B : tiny);
    }
};

// The terms above of one evaluation, in that order: conductor_fresnel's value and conductor_fresnel_gradient's
// derivatives are both taken from them.
template <class T>
ConductorFresnelTerms<T> conductor_fresnel_terms(const T& n, const T& k2, const T& nk, const T& mu) {
    using std::abs;
    ConductorFresnelTerms<T> c;
    c.mu2 = mu * mu;
    c.s2 = T(1) - c.mu2;
    c.t = n * n - k2 - T(1) + c.mu2;
    c.r = nonnegative_sqrt(c.t * c.t + T(4) * n * n * k2);
    c.p = nonnegative_sqrt(T(0.5) * (c.r + abs(c.t)));
    c.t_positive = c.t >= T(0);
    c.num = c.t_positive ? c.p : nk;
    c.den = c.t_positive ? T(1) : c.p;
    c.X = c.r + c.mu2;
    c.Q = c.mu2 * c.r + c.s2 * c.s2;
    c.two_num_mu = T(2) * c.num * mu;
    c.Ns = c.den * c.X - c.two_num_mu;
    c.Ds = c.den * c.X + c.two_num_mu;
    c.Dp = c.den * c.Q + c.two_num_mu * c.s2;
    c.B = c.Ds * c.Dp;
    return c;
}

template <class T>
T conductor_fresnel(const T& n, const T& k2, const T& nk, const T& mu) {
    return conductor_fresnel_terms(n, k2, nk, mu).value();
}

// conductor_fresnel's value and its derivatives in its three inputs n, k² and nk, taken as independent (each model
// applies its own chain rule: conductor-rgb's k² = k·k and nk, gulbrandsen's map of (r, g)). In closed form, not
// the Jets' operations: the derivatives agree with autodiff's to rounding (tests/test_conductor_gradient.cpp), at a
// fraction of the cost. The value is conductor_fresnel's, bit for bit. Where a square root's argument is 0 its
// derivative is 0, as sqrt_or_zero gives Jets; at μ = 0 every derivative is 0 (F = 1 there for every η ≠ 1).
struct ConductorFresnelGradient {
    double value, d_n, d_k2, d_nk;
};

inline ConductorFresnelGradient conductor_fresnel_gradient(double n, double k2, double nk, double mu) {
    const ConductorFresnelTerms<double> c = conductor_fresnel_terms(n, k2, nk, mu);
    const auto& [mu2, s2, t, r, p, t_positive, num, den, X, Q, two_num_mu, Ns, Ds, Dp, B] = c;
    const double F = c.value();
    const double w = den * Q;
    if (!(mu > 0.0)) return {F, 0.0, 0.0, 0.0};
    // With u = den X, v = 2 num μ (N_s = u − v, D_s = u + v), w = den Q, z = 2 num s² μ (D_p = w + z), F = N_s w / (D_s D_p)
    // and ln F = ln(N_s / D_s) + ln w − ln D_p give dF = [2 w D_p (v du − u dv) + N_s D_s (z dw − w dz)] / (D_s D_p)²:
    // in r, num and den each a sum of terms of one sign, so nothing cancels (not even as μ → 0, where the Jets'
    // (dA − F dB) / B loses digits). The parts F_r, F_num, F_den are taken with num and den fixed.
    const double v = two_num_mu, z = two_num_mu * s2, u = den * X;
    const double inv_B2 = 1.0 / (B * B);
    const double w_Dp = w * Dp, Ns_Ds = Ns * Ds;
    const double F_r = den * (2.0 * w_Dp * v + Ns_Ds * z * mu2) * inv_B2;
    const double F_num = -2.0 * mu * w * (2.0 * Dp * u + s2 * Ns_Ds) * inv_B2;
    const double F_den = (2.0 * w_Dp * v * X + Ns_Ds * z * Q) * inv_B2;
    // r² = t² + 4n²k², t = n² − k² − s²: dr/dn = 2n (t + 2k²) / r, dr/dk² = (2n² − t) / r.
    const double inv_r = r > 0.0 ? 1.0 / r : 0.0;
    const double r_n = 2.0 * n * (t + 2.0 * k2) * inv_r, r_k2 = (2.0 * n * n - t) * inv_r;
    // p² = (r + |t|) / 2: dp = (dr + sign(t) dt) / 4p, dt/dn = 2n, dt/dk² = −1.
    const double sign_t = std::copysign(1.0, t);  // abs's derivative as the Jets take it
    const double inv_4p = p > 0.0 ? 0.25 / p : 0.0;
    const double p_n = (r_n + sign_t * 2.0 * n) * inv_4p, p_k2 = (r_k2 - sign_t) * inv_4p;
    // t ≥ 0: num = p, den = 1; t < 0: num = nk, den = p.
    const double F_p = t_positive ? F_num : F_den;
    return {F, F_r * r_n + F_p * p_n, F_r * r_k2 + F_p * p_k2, t_positive ? 0.0 : F_num};
}

// One node of a fit's target as the analytic gradients take it (evaluate_with_gradient): μ clamped, m = 1 − μ and
// ln m, computed once per node rather than once per evaluation.
struct CurveNode {
    double mu, m, log_m;
    static CurveNode at(double mu_in) {
        const double mu = clamp_mu(mu_in), m = 1.0 - mu;
        return {mu, m, std::log(m)};
    }
};

// mᵉ of a node and its derivative in e, with the operations of Ceres's pow(Jet, Jet) for a constant base
// (ceres/jet.h: value pow(m, e), derivative pow(m, e) · ln m; at m = 0: 0 and a zero derivative for e ≥ 1, NaN
// below), so that an analytic Jacobian built from it is the one autodiff gives, bit for bit.
inline double node_power(const CurveNode& node, double e, double& d_de) {
    if (node.m == 0.0 && e >= 1.0) {
        d_de = 0.0;
        return e > 1.0 ? 0.0 : node.m;
    }
    const double value = std::pow(node.m, e);
    d_de = node.m == 0.0 ? std::numeric_limits<double>::quiet_NaN() : value * node.log_m;
    return value;
}

// Where a node power's derivative is NaN (m = 0, e < 1) the Jets' NaN reaches every derivative of the curve (their
// e·m^(e−1) · 0 term): the gradient is set to NaN as a whole, as autodiff gives it.
inline void spread_undefined_derivative(double d_de, double* gradient, int count) {
    if (std::isnan(d_de))
        for (int i = 0; i < count; ++i) gradient[i] = std::numeric_limits<double>::quiet_NaN();
}

}  // namespace metalfit::model_math
