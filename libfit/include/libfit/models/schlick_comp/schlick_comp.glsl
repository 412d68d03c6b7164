// Schlick with Lazányi's compensation, F0 free: F(μ) = F0 + (1 − F0)(1 − μ)^5 − a μ (1 − μ)^α, per channel.
#ifndef METALFIT_SCHLICK_COMP_GLSL  // the file may be included more than once
#define METALFIT_SCHLICK_COMP_GLSL
vec3 metalfit_schlick_comp(vec3 F0, vec3 a, vec3 alpha, float mu) {
    mu = mu < 0.0 ? 0.0 : (mu > 1.0 ? 1.0 : mu);  // a cosine a hair outside [0, 1] gives the end value (model_math::clamp_mu)
    float m = 1.0 - mu;
    float m2 = m * m;
    return F0 + (vec3(1.0) - F0) * (m2 * m2 * m) - a * mu * pow(vec3(m), alpha);
}
#endif  // METALFIT_SCHLICK_COMP_GLSL
