// Schlick (1994): F(μ) = F0 + (1 − F0)(1 − μ)^5, per channel.
vec3 metalfit_schlick(vec3 F0, float mu) {
    float m = 1.0 - mu;
    float m2 = m * m;
    return F0 + (vec3(1.0) - F0) * (m2 * m2 * m);
}
