// Schlick (1994): F(μ) = F0 + (1 − F0)(1 − μ)^5, per channel. WGSL of schlick.glsl, line for line.
fn metalfit_schlick(F0: vec3f, mu_in: f32) -> vec3f {
    let mu = select(select(mu_in, 1.0, mu_in > 1.0), 0.0, mu_in < 0.0);  // mu < 0 ? 0 : (mu > 1 ? 1 : mu), as the GLSL
    let m = 1.0 - mu;
    let m2 = m * m;
    return F0 + (vec3f(1.0) - F0) * (m2 * m2 * m);
}
