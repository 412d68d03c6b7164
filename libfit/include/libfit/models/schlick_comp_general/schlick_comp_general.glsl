// The generalised compensated Schlick: F(μ) = F0 + (1 − F0)(1 − μ)^p − a μ (1 − μ)^α, per channel.
#ifndef METALFIT_SCHLICK_COMP_GENERAL_GLSL  // the file may be included more than once
#define METALFIT_SCHLICK_COMP_GENERAL_GLSL
vec3 metalfit_schlick_comp_general(vec3 F0, vec3 p, vec3 a, vec3 alpha, float mu) {
    mu = mu < 0.0 ? 0.0 : (mu > 1.0 ? 1.0 : mu);  // a cosine a hair outside [0, 1] gives the end value (model_math::clamp_mu)
    vec3 m = vec3(1.0 - mu);
    return F0 + (vec3(1.0) - F0) * pow(m, p) - a * mu * pow(m, alpha);
}
#endif  // METALFIT_SCHLICK_COMP_GENERAL_GLSL
