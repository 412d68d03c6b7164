// Schlick with a linear two-term compensation: F(μ) = F0 + (1 − F0) m^5 − b1 μ m^4 − b2 μ m^9, m = 1 − μ, per channel.
// WGSL of schlick_comp_linear.glsl, line for line.
fn metalfit_schlick_comp_linear(F0: vec3f, b1: vec3f, b2: vec3f, mu_in: f32) -> vec3f {
    let mu = select(select(mu_in, 1.0, mu_in > 1.0), 0.0, mu_in < 0.0);  // mu < 0 ? 0 : (mu > 1 ? 1 : mu), as the GLSL
    let m = 1.0 - mu;
    let m2 = m * m;
    let m4 = m2 * m2;
    return F0 + (vec3f(1.0) - F0) * (m4 * m) - mu * m4 * (b1 + b2 * (m4 * m));
}
