// Exact unpolarised Fresnel reflectance of a conductor η = n + i k per channel, in the real form of the thesis
// (eq. 1.5–1.6) rearranged so that nothing is divided by μ and nothing cancels for large k:
//   t = n² − k² − s², r = |η² − s²| = sqrt(t² + 4n²k²), a = Re sqrt(η² − s²)  (s² = 1 − μ²),
//   F_s = (r − 2aμ + μ²) / (r + 2aμ + μ²),  F_p = F_s (μ²r − 2as²μ + s⁴) / (μ²r + 2as²μ + s⁴).
// Takes k² (r uses 4n²k²) and nk (only where t < 0, a = nk / b), as libfit/include/libfit/model_math.hpp does.
#ifndef METALFIT_CONDUCTOR_RGB_GLSL  // the file may be included more than once
#define METALFIT_CONDUCTOR_RGB_GLSL
vec3 metalfit_conductor_fresnel(vec3 n, vec3 k2, vec3 nk, float mu) {
    mu = mu < 0.0 ? 0.0 : (mu > 1.0 ? 1.0 : mu);  // a cosine a hair outside [0, 1] gives the end value (model_math::clamp_mu)
    float s2 = 1.0 - mu * mu;
    vec3 t = n * n - k2 - s2;
    vec3 r = sqrt(t * t + 4.0 * n * n * k2);
    vec3 a_pos = sqrt(max(0.5 * (r + t), 0.0));
    vec3 b_neg = sqrt(max(0.5 * (r - t), 0.0));
    vec3 a = mix(nk / max(b_neg, vec3(1e-30)), a_pos, greaterThanEqual(t, vec3(0.0)));
    vec3 mu2r = mu * mu * r;
    vec3 Fs = (r - 2.0 * a * mu + mu * mu) / (r + 2.0 * a * mu + mu * mu);
    vec3 Fp = Fs * (mu2r - 2.0 * a * s2 * mu + s2 * s2) / (mu2r + 2.0 * a * s2 * mu + s2 * s2);
    vec3 F = 0.5 * (Fs + Fp);
    return mu > 0.0 ? F : mix(vec3(1.0), vec3(0.0), equal(r, vec3(0.0)));
}

vec3 metalfit_conductor_rgb(vec3 n, vec3 k, float mu) {
    mu = mu < 0.0 ? 0.0 : (mu > 1.0 ? 1.0 : mu);  // a cosine a hair outside [0, 1] gives the end value (model_math::clamp_mu)
    return metalfit_conductor_fresnel(n, k * k, n * k, mu);
}
#endif  // METALFIT_CONDUCTOR_RGB_GLSL
