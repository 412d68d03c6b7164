// Lazányi's rescaled Schlick (thesis eq. 3.2): Schlick with the exact normal-incidence reflectance of η = n + i k,
// F*(μ) = ((n − 1)² + k² + 4n(1 − μ)^5) / ((n + 1)² + k²).
#ifndef METALFIT_LAZANYI_GLSL  // the file may be included more than once
#define METALFIT_LAZANYI_GLSL
vec3 metalfit_lazanyi(vec3 n, vec3 k, float mu) {
    mu = mu < 0.0 ? 0.0 : (mu > 1.0 ? 1.0 : mu);  // a cosine a hair outside [0, 1] gives the end value (model_math::clamp_mu)
    float m = 1.0 - mu;
    float m2 = m * m;
    vec3 k2 = k * k;
    return ((n - 1.0) * (n - 1.0) + k2 + 4.0 * n * (m2 * m2 * m)) / ((n + 1.0) * (n + 1.0) + k2);
}
#endif  // METALFIT_LAZANYI_GLSL
