// Gulbrandsen (2014) artist-friendly metallic Fresnel: reflectivity r and edge tint g mapped to n, k, then the exact
// conductor Fresnel. n_min = (1 − r)/(1 + r), n_max = (1 + √r)/(1 − √r), n = g n_min + (1 − g) n_max,
// k² = (r (n + 1)² − (n − 1)²) / (1 − r), factored as g (n_max − n_min)(n − n₋) with n₋ = (1 − √r)/(1 + √r), which is
// exactly 0 at g = 0 (see libfit/include/libfit/models/gulbrandsen/gulbrandsen.hpp).
#ifndef METALFIT_GULBRANDSEN_GLSL  // the file may be included more than once
#define METALFIT_GULBRANDSEN_GLSL
vec3 metalfit_gulbrandsen_n(vec3 r, vec3 g) {
    vec3 sr = sqrt(r);
    vec3 n_min = (vec3(1.0) - r) / (vec3(1.0) + r);
    vec3 n_max = (vec3(1.0) + sr) / (vec3(1.0) - sr);
    return g * n_min + (vec3(1.0) - g) * n_max;
}

vec3 metalfit_gulbrandsen_k2(vec3 r, vec3 g) {
    vec3 sr = sqrt(r);
    vec3 n_max = (vec3(1.0) + sr) / (vec3(1.0) - sr);
    vec3 n_min = (vec3(1.0) - r) / (vec3(1.0) + r);
    vec3 n_minus = (vec3(1.0) - sr) / (vec3(1.0) + sr);
    return max(g * (n_max - n_min) * (metalfit_gulbrandsen_n(r, g) - n_minus), vec3(0.0));
}

vec3 metalfit_gulbrandsen(vec3 r, vec3 g, float mu) {
    mu = mu < 0.0 ? 0.0 : (mu > 1.0 ? 1.0 : mu);  // a cosine a hair outside [0, 1] gives the end value (model_math::clamp_mu)
    vec3 n = metalfit_gulbrandsen_n(r, g);
    vec3 k2 = metalfit_gulbrandsen_k2(r, g);
    return metalfit_conductor_fresnel(n, k2, n * sqrt(k2), mu);
}
#endif  // METALFIT_GULBRANDSEN_GLSL
