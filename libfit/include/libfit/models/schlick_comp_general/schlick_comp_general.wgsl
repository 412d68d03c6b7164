// The generalised compensated Schlick: F(μ) = F0 + (1 − F0)(1 − μ)^p − a μ (1 − μ)^α, per channel.
// WGSL of schlick_comp_general.glsl, line for line.
fn metalfit_schlick_comp_general(F0: vec3f, p: vec3f, a: vec3f, alpha: vec3f, mu_in: f32) -> vec3f {
    let mu = select(select(mu_in, 1.0, mu_in > 1.0), 0.0, mu_in < 0.0);  // mu < 0 ? 0 : (mu > 1 ? 1 : mu), as the GLSL
    let m = vec3f(1.0 - mu);
    // m^alpha is 0 at m = 0 (mu = 1) written out: pow's accuracy is exp2(alpha log2(m))'s, and SwiftShader's log2(0)
    // is finite (pow(0, 0.05) = 0.0127 there, where libfit and the GLSL give 0).
    return F0 + (vec3f(1.0) - F0) * pow(m, p) - a * mu * select(pow(m, alpha), vec3f(0.0), m <= vec3f(0.0));
}
