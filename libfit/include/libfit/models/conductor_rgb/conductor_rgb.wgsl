// Exact unpolarised Fresnel reflectance of a conductor η = n + i k per channel: WGSL of conductor_rgb.glsl, line for
// line (see there for the form: nothing divided by μ, nothing cancelling for large k; one division left).
fn metalfit_conductor_fresnel(n: vec3f, k2: vec3f, nk: vec3f, mu_in: f32) -> vec3f {
    let mu = select(select(mu_in, 1.0, mu_in > 1.0), 0.0, mu_in < 0.0);  // mu < 0 ? 0 : (mu > 1 ? 1 : mu), as the GLSL
    let mu2 = mu * mu;
    let s2 = 1.0 - mu2;
    let t = n * n - k2 - 1.0 + mu2;
    let r = sqrt(t * t + 4.0 * n * n * k2);
    let p = sqrt(0.5 * (r + max(t, -t)));
    let num = select(nk, p, t >= vec3f(0.0));
    let den = select(p, vec3f(1.0), t >= vec3f(0.0));
    let X = r + mu2;
    let Q = mu2 * r + s2 * s2;
    let two_num_mu = 2.0 * num * mu;
    let Ns = den * X - two_num_mu;
    let Ds = den * X + two_num_mu;
    let Dp = den * Q + two_num_mu * s2;
    let B = Ds * Dp;
    return Ns * (den * Q) / max(B, vec3f(1e-30));
}

fn metalfit_conductor_rgb(n: vec3f, k: vec3f, mu_in: f32) -> vec3f {
    let mu = select(select(mu_in, 1.0, mu_in > 1.0), 0.0, mu_in < 0.0);  // mu < 0 ? 0 : (mu > 1 ? 1 : mu), as the GLSL
    return metalfit_conductor_fresnel(n, k * k, n * k, mu);
}
