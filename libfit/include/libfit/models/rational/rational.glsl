// A rational curve per channel: F(μ) = (1 + a μ + b μ^2) / (1 + c μ + d μ^2).
#ifndef METALFIT_RATIONAL_GLSL  // the file may be included more than once
#define METALFIT_RATIONAL_GLSL
vec3 metalfit_rational(vec3 a, vec3 b, vec3 c, vec3 d, float mu) {
    mu = mu < 0.0 ? 0.0 : (mu > 1.0 ? 1.0 : mu);  // a cosine a hair outside [0, 1] gives the end value (model_math::clamp_mu)
    return (vec3(1.0) + mu * (a + b * mu)) / (vec3(1.0) + mu * (c + d * mu));
}
#endif  // METALFIT_RATIONAL_GLSL
