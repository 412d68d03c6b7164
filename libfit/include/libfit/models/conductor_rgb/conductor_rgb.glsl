// Exact unpolarised Fresnel reflectance of a conductor η = n + i k per channel, in the real form of the thesis
// (eq. 1.5–1.6) rearranged so that nothing is divided by μ and nothing cancels for large k:
//   t = n² − k² − s², r = |η² − s²| = sqrt(t² + 4n²k²), a = Re sqrt(η² − s²)  (s² = 1 − μ²),
//   F_s = (r − 2aμ + μ²) / (r + 2aμ + μ²),  F_p = F_s (μ²r − 2as²μ + s⁴) / (μ²r + 2as²μ + s⁴),  F = (F_s + F_p)/2,
// with a = num/den multiplied through so that one division is left: (num, den) = (p, 1) where t ≥ 0 and (nk, p)
// where t < 0 (a = nk / b), p = sqrt((r + |t|)/2), and F = N_s den (μ²r + s⁴) / (D_s D_p), t = (n² − k² − 1) + μ²;
// at μ = 0 that is 1 exactly, and 0 for η = 1 (the denominator held at 1e-30).
// Takes k² (r uses 4n²k²) and nk (only where t < 0), as libfit/include/libfit/models/model_math.hpp does, line for
// line (|t| written max(t, −t)).
#ifndef METALFIT_CONDUCTOR_RGB_GLSL  // the file may be included more than once
#define METALFIT_CONDUCTOR_RGB_GLSL
vec3 metalfit_conductor_fresnel(vec3 n, vec3 k2, vec3 nk, float mu) {
    mu = mu < 0.0 ? 0.0 : (mu > 1.0 ? 1.0 : mu);  // a cosine a hair outside [0, 1] gives the end value (model_math::clamp_mu)
    float mu2 = mu * mu;
    float s2 = 1.0 - mu2;
    vec3 t = n * n - k2 - 1.0 + mu2;
    vec3 r = sqrt(t * t + 4.0 * n * n * k2);
    vec3 p = sqrt(0.5 * (r + max(t, -t)));
    vec3 num = mix(nk, p, greaterThanEqual(t, vec3(0.0)));
    vec3 den = mix(p, vec3(1.0), greaterThanEqual(t, vec3(0.0)));
    vec3 X = r + mu2;
    vec3 Q = mu2 * r + s2 * s2;
    vec3 two_num_mu = 2.0 * num * mu;
    vec3 Ns = den * X - two_num_mu;
    vec3 Ds = den * X + two_num_mu;
    vec3 Dp = den * Q + two_num_mu * s2;
    vec3 B = Ds * Dp;
    return Ns * (den * Q) / max(B, vec3(1e-30));
}

vec3 metalfit_conductor_rgb(vec3 n, vec3 k, float mu) {
    mu = mu < 0.0 ? 0.0 : (mu > 1.0 ? 1.0 : mu);  // a cosine a hair outside [0, 1] gives the end value (model_math::clamp_mu)
    return metalfit_conductor_fresnel(n, k * k, n * k, mu);
}
#endif  // METALFIT_CONDUCTOR_RGB_GLSL
