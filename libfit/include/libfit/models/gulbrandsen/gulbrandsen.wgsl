// Gulbrandsen (2014) artist-friendly metallic Fresnel: reflectivity r and edge tint g mapped to n, k, then the exact
// conductor Fresnel. WGSL of gulbrandsen.glsl, line for line (see there for the factored k²).
fn metalfit_gulbrandsen_n(r: vec3f, g: vec3f) -> vec3f {
    let sr = sqrt(r);
    let n_min = (vec3f(1.0) - r) / (vec3f(1.0) + r);
    let n_max = (vec3f(1.0) + sr) / (vec3f(1.0) - sr);
    return g * n_min + (vec3f(1.0) - g) * n_max;
}

fn metalfit_gulbrandsen_k2(r: vec3f, g: vec3f) -> vec3f {
    let sr = sqrt(r);
    let n_max = (vec3f(1.0) + sr) / (vec3f(1.0) - sr);
    let n_min = (vec3f(1.0) - r) / (vec3f(1.0) + r);
    let n_minus = (vec3f(1.0) - sr) / (vec3f(1.0) + sr);
    return max(g * (n_max - n_min) * (metalfit_gulbrandsen_n(r, g) - n_minus), vec3f(0.0));
}

fn metalfit_gulbrandsen(r: vec3f, g: vec3f, mu_in: f32) -> vec3f {
    let mu = select(select(mu_in, 1.0, mu_in > 1.0), 0.0, mu_in < 0.0);  // mu < 0 ? 0 : (mu > 1 ? 1 : mu), as the GLSL
    let n = metalfit_gulbrandsen_n(r, g);
    let k2 = metalfit_gulbrandsen_k2(r, g);
    return metalfit_conductor_fresnel(n, k2, n * sqrt(k2), mu);
}
