// Schlick with Lazányi's compensation, F0 free: F(μ) = F0 + (1 − F0)(1 − μ)^5 − a μ (1 − μ)^α, per channel.
// WGSL of schlick_comp.glsl, line for line.
fn metalfit_schlick_comp(F0: vec3f, a: vec3f, alpha: vec3f, mu_in: f32) -> vec3f {
    let mu = select(select(mu_in, 1.0, mu_in > 1.0), 0.0, mu_in < 0.0);  // mu < 0 ? 0 : (mu > 1 ? 1 : mu), as the GLSL
    let m = 1.0 - mu;
    let m2 = m * m;
    // m^alpha is 0 at m = 0 (mu = 1) written out: pow's accuracy is exp2(alpha log2(m))'s, and SwiftShader's log2(0)
    // is finite (pow(0, 0.05) = 0.0127 there, where libfit and the GLSL give 0).
    return F0 + (vec3f(1.0) - F0) * (m2 * m2 * m) - a * mu * select(pow(vec3f(m), alpha), vec3f(0.0), vec3f(m) <= vec3f(0.0));
}
