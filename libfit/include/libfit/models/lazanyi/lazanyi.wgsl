// Lazányi's rescaled Schlick (thesis eq. 3.2): F*(μ) = ((n − 1)² + k² + 4n(1 − μ)^5) / ((n + 1)² + k²).
// WGSL of lazanyi.glsl, line for line.
fn metalfit_lazanyi(n: vec3f, k: vec3f, mu_in: f32) -> vec3f {
    let mu = select(select(mu_in, 1.0, mu_in > 1.0), 0.0, mu_in < 0.0);  // mu < 0 ? 0 : (mu > 1 ? 1 : mu), as the GLSL
    let m = 1.0 - mu;
    let m2 = m * m;
    let k2 = k * k;
    return ((n - 1.0) * (n - 1.0) + k2 + 4.0 * n * (m2 * m2 * m)) / ((n + 1.0) * (n + 1.0) + k2);
}
