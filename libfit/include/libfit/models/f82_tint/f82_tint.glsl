// F82-tint (Hoffman 2019, Adobe Standard Material, OpenPBR): Schlick minus μ(1 − μ)^6 b, with b chosen so that
// F(μ̄) = tint · Schlick(F0, μ̄) at μ̄ = 1/7 (θ ≈ 81.8°).
#ifndef METALFIT_F82_TINT_GLSL  // the file may be included more than once
#define METALFIT_F82_TINT_GLSL
vec3 metalfit_f82_tint(vec3 F0, vec3 tint, float mu) {
    mu = mu < 0.0 ? 0.0 : (mu > 1.0 ? 1.0 : mu);  // a cosine a hair outside [0, 1] gives the end value (model_math::clamp_mu)
    const float mu_bar = 1.0 / 7.0;
    const float m_bar = 1.0 - mu_bar;
    float m = 1.0 - mu;
    float m6 = m * m * m;
    m6 = m6 * m6;
    float m6_bar = m_bar * m_bar * m_bar;
    m6_bar = m6_bar * m6_bar;
    vec3 b = (vec3(1.0) - tint) * metalfit_schlick(F0, mu_bar) / (mu_bar * m6_bar);
    return metalfit_schlick(F0, mu) - b * (mu * m6);
}
#endif  // METALFIT_F82_TINT_GLSL
