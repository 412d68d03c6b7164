// Lazányi's error-compensated rescaled Schlick (thesis eq. 3.3): F**(μ) = F*(μ) − a μ (1 − μ)^α.
// WGSL of lazanyi_comp.glsl, line for line.
fn metalfit_lazanyi_comp(n: vec3f, k: vec3f, a: vec3f, alpha: vec3f, mu_in: f32) -> vec3f {
    let mu = select(select(mu_in, 1.0, mu_in > 1.0), 0.0, mu_in < 0.0);  // mu < 0 ? 0 : (mu > 1 ? 1 : mu), as the GLSL
    return metalfit_lazanyi(n, k, mu) - a * mu * pow(vec3f(1.0 - mu), alpha);
}
