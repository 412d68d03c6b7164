// Localized reflections: where does the reflection ray from shaded point x (relative to the reference point o)
// in unit direction R hit the environment stored in the cube map u_env (rgb radiance, a distance from o)?
// Returns the cube-map lookup direction (not normalised). Thesis ch. 4 (FORMULAS.md §5); Lagarde & Zanuttini 2012.
// REFLECTION_CLASSIC | REFLECTION_BOX_PARALLAX | REFLECTION_DISTANCE_IMPOSTOR; with the impostor one of
// STRATEGY_SECANT | STRATEGY_FALSE_POSITION | STRATEGY_MIXED and NITER (refinement steps, each one cube lookup).
uniform samplerCube u_env;

#if defined(REFLECTION_CLASSIC)
vec3 reflection_lookup(vec3 x, vec3 R) { return R; }

#elif defined(REFLECTION_BOX_PARALLAX)
uniform vec3 u_box_parallax_min;  // room box relative to o
uniform vec3 u_box_parallax_max;
vec3 reflection_lookup(vec3 x, vec3 R) {
    vec3 t_max = (u_box_parallax_max - x) / R;
    vec3 t_min = (u_box_parallax_min - x) / R;
    vec3 t = max(t_max, t_min);
    return x + R * min(t.x, min(t.y, t.z));
}

#elif defined(REFLECTION_DISTANCE_IMPOSTOR)
float env_distance(vec3 direction) { return textureLod(u_env, direction, 0.0).a; }
// ρ(p) = |p| / D(p/|p|): < 1 undershoot (in front of the environment), > 1 overshoot.
float impostor_rho(vec3 p) { return length(p) / env_distance(p); }
// eq. 4.4: pair guess d (with ρ) with the point at infinity.
float pair_with_infinity(float d, float rho, float DR) { return max(d + DR * (1.0 - rho), 0.0); }
// eq. 4.6: the ray parameter where the line through (d_a, ρ_a), (d_b, ρ_b) reaches ρ = 1.
float refine(float d_a, float rho_a, float d_b, float rho_b) {
    float denominator = rho_b - rho_a;
    if (abs(denominator) < 1e-7) return d_b;
    return max(d_b + (d_b - d_a) * (1.0 - rho_b) / denominator, 0.0);
}

vec3 reflection_lookup(vec3 x, vec3 R) {
    float DR = env_distance(R);
#if defined(STRATEGY_SECANT)
    // Start: the perpendicular-surface guess (eq. 4.2), then its pairing with infinity (eq. 4.4); each step pairs
    // the last two guesses (eq. 4.6).
    float d_prev = max(DR - dot(x, R), 0.0);
    float rho_prev = impostor_rho(x + R * d_prev);
    float d = pair_with_infinity(d_prev, rho_prev, DR);
    for (int i = 0; i < NITER; ++i) {
        float rho = impostor_rho(x + R * d);
        float d_next = refine(d_prev, rho_prev, d, rho);
        d_prev = d;
        rho_prev = rho;
        d = d_next;
    }
#else
    // False position starts at the shaded point (d = 0, an undershoot inside the room); mixed starts at the
    // perpendicular guess (eq. 4.2). Both keep the last undershoot and the last overshoot and pair a new guess
    // with the opposite type (eq. 4.6), or with infinity (eq. 4.4) while that type is missing.
#if defined(STRATEGY_FALSE_POSITION)
    float d0 = 0.0;
#else
    float d0 = max(DR - dot(x, R), 0.0);
#endif
    float d_under = 0.0, rho_under = 0.0, d_over = 0.0, rho_over = 0.0;
    bool has_under = false, has_over = false;
    float d = d0;
    for (int i = 0; i <= NITER; ++i) {
        float rho = impostor_rho(x + R * d);
        if (rho < 1.0) {
            d_under = d;
            rho_under = rho;
            has_under = true;
        } else {
            d_over = d;
            rho_over = rho;
            has_over = true;
        }
        if (has_under && has_over) d = refine(d_under, rho_under, d_over, rho_over);
        else d = pair_with_infinity(d, rho, DR);
    }
#endif
    return x + R * d;
}
#endif
