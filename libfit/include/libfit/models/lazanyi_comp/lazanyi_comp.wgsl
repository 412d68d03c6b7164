// Lazányi's error-compensated rescaled Schlick (thesis eq. 3.3): F**(μ) = F*(μ) − a μ (1 − μ)^α.
// WGSL of lazanyi_comp.glsl, line for line.
fn metalfit_lazanyi_comp(n: vec3f, k: vec3f, a: vec3f, alpha: vec3f, mu_in: f32) -> vec3f {
    let mu = select(select(mu_in, 1.0, mu_in > 1.0), 0.0, mu_in < 0.0);  // mu < 0 ? 0 : (mu > 1 ? 1 : mu), as the GLSL
    // m^alpha is 0 at m = 0 (mu = 1) written out: pow's accuracy is exp2(alpha log2(m))'s, and SwiftShader's log2(0)
    // is finite (pow(0, 0.05) = 0.0127 there, where libfit and the GLSL give 0).
    return metalfit_lazanyi(n, k, mu) - a * mu * select(pow(vec3f(1.0 - mu), alpha), vec3f(0.0), vec3f(1.0 - mu) <= vec3f(0.0));
}
