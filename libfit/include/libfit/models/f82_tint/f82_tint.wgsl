// F82-tint (Hoffman 2019, Adobe Standard Material, OpenPBR): Schlick minus μ(1 − μ)^6 b, with b chosen so that
// F(μ̄) = tint · Schlick(F0, μ̄) at μ̄ = 1/7 (θ ≈ 81.8°). WGSL of f82_tint.glsl, line for line.
fn metalfit_f82_tint(F0: vec3f, tint: vec3f, mu_in: f32) -> vec3f {
    let mu = select(select(mu_in, 1.0, mu_in > 1.0), 0.0, mu_in < 0.0);  // mu < 0 ? 0 : (mu > 1 ? 1 : mu), as the GLSL
    const mu_bar: f32 = 1.0 / 7.0;
    const m_bar: f32 = 1.0 - mu_bar;
    let m = 1.0 - mu;
    var m6 = m * m * m;
    m6 = m6 * m6;
    var m6_bar = m_bar * m_bar * m_bar;
    m6_bar = m6_bar * m6_bar;
    let b = (vec3f(1.0) - tint) * metalfit_schlick(F0, mu_bar) / (mu_bar * m6_bar);
    return metalfit_schlick(F0, mu) - b * (mu * m6);
}
