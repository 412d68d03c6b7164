// A rational curve per channel: F(μ) = (1 + a μ + b μ^2) / (1 + c μ + d μ^2). WGSL of rational.glsl, line for line.
fn metalfit_rational(a: vec3f, b: vec3f, c: vec3f, d: vec3f, mu_in: f32) -> vec3f {
    let mu = select(select(mu_in, 1.0, mu_in > 1.0), 0.0, mu_in < 0.0);  // mu < 0 ? 0 : (mu > 1 ? 1 : mu), as the GLSL
    return (vec3f(1.0) + mu * (a + b * mu)) / (vec3f(1.0) + mu * (c + d * mu));
}
