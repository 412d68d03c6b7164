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

// Exact unpolarised Fresnel reflectance of η = n + i k from vacuum, in the thesis's real form (eq. 1.5–1.6)
// rearranged so that nothing is divided by μ and nothing cancels for large k: t = n² − k² − s², r = sqrt(t² + 4n²k²) =
// |η² − s²|, a = Re sqrt(η² − s²), s² = 1 − μ². p = sqrt((r + |t|)/2) is a where t ≥ 0 and b = Im sqrt(η² − s²) where
// t < 0, and there a = nk / b (ab = nk), not sqrt((r + t)/2), which cancels for large k.
// Takes k² (r uses 4n²k²) and nk (only where t < 0), so that Gulbrandsen's k² = 0 keeps its derivative.
//
// Branch-free: both sides of every case are computed and selected (blends for float and double, so that an array
// loop over it vectorises when built without errno, docs/fitting.md), the same values and Jet derivatives as taking
// one side. The GLSL function, line for line (conductor_rgb.glsl, metalfit_conductor_fresnel; the C++ export is that
// GLSL): s2, t, r; p is its a_pos where t ≥ 0 and its b_neg where t < 0; a is its mix(nk / max(b_neg, 1e-30), a_pos,
// t ≥ 0) (the guard is never reached where that side is taken: b ≥ sqrt(|t|)); Fs, Fp, F and the grazing select.
template <class T>
T conductor_fresnel(const T& n, const T& k2, const T& nk, const T& mu) {
    using std::abs;
    const T tiny = smallest_normal<T>();
    const T s2 = T(1) - mu * mu;
    const T t = n * n - k2 - s2;
    const T r = sqrt_or_zero(t * t + T(4) * n * n * k2);
    const T p = sqrt_or_zero(T(0.5) * (r + abs(t)));
    const T a_of_b = nk / (p > tiny ? p : tiny);  // computed on both sides: a select, not a branch around a division
    const T a = t >= T(0) ? p : a_of_b;
    const T mu2 = mu * mu;
    const T Fs = (r - T(2) * a * mu + mu2) / (r + T(2) * a * mu + mu2);
    const T Fp = Fs * (mu2 * r - T(2) * a * s2 * mu + s2 * s2) / (mu2 * r + T(2) * a * s2 * mu + s2 * s2);
    const T F = T(0.5) * (Fs + Fp);
    const T grazing = r > T(0) ? T(1) : T(0);  // F(0) = 1; η = 1 has no interface (there F is 0/0 and not taken)
    return mu > T(0) ? F : grazing;
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
