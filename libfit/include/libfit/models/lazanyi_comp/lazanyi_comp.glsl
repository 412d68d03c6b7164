// Lazányi's error-compensated rescaled Schlick (thesis eq. 3.3): F**(μ) = F*(μ) − a μ (1 − μ)^α.
#ifndef METALFIT_LAZANYI_COMP_GLSL  // the file may be included more than once
#define METALFIT_LAZANYI_COMP_GLSL
vec3 metalfit_lazanyi_comp(vec3 n, vec3 k, vec3 a, vec3 alpha, float mu) {
    mu = mu < 0.0 ? 0.0 : (mu > 1.0 ? 1.0 : mu);  // a cosine a hair outside [0, 1] gives the end value (model_math::clamp_mu)
    return metalfit_lazanyi(n, k, mu) - a * mu * pow(vec3(1.0 - mu), alpha);
}
#endif  // METALFIT_LAZANYI_COMP_GLSL
