// Schlick with a linear two-term compensation: F(μ) = F0 + (1 − F0) m^5 − b1 μ m^4 − b2 μ m^9, m = 1 − μ, per channel.
#ifndef METALFIT_SCHLICK_COMP_LINEAR_GLSL  // the file may be included more than once
#define METALFIT_SCHLICK_COMP_LINEAR_GLSL
vec3 metalfit_schlick_comp_linear(vec3 F0, vec3 b1, vec3 b2, float mu) {
    mu = mu < 0.0 ? 0.0 : (mu > 1.0 ? 1.0 : mu);  // a cosine a hair outside [0, 1] gives the end value (model_math::clamp_mu)
    float m = 1.0 - mu;
    float m2 = m * m;
    float m4 = m2 * m2;
    return F0 + (vec3(1.0) - F0) * (m4 * m) - mu * m4 * (b1 + b2 * (m4 * m));
}
#endif  // METALFIT_SCHLICK_COMP_LINEAR_GLSL
