// Localized reflections: where does the reflection ray from shaded point x (relative to the reference point o)
// in unit direction R hit the environment stored in the cube map u_env (rgb radiance, a distance from o)?
// Returns the cube-map lookup direction (not normalised). Thesis ch. 4 (docs/preview.md, "The technique"); Lagarde & Zanuttini 2012.
// REFLECTION_CLASSIC | REFLECTION_BOX_PARALLAX | REFLECTION_DISTANCE_IMPOSTOR; with the impostor one of
// STRATEGY_SECANT | STRATEGY_FALSE_POSITION | STRATEGY_MIXED (the thesis's three) | STRATEGY_ILLINOIS |
// STRATEGY_SAFE_SECANT (safeguarded), NITER (at most this many refinement steps, each one cube lookup), TOLERANCE
// and, for the safeguarded ones, SEARCH_STEPS (the linear search that brackets the first crossing; 0: none).
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
// TOLERANCE: a pixel stops refining once |ρ − 1| < TOLERANCE at its latest guess (0: always NITER steps).
// g_iterations_taken: refinement steps this pixel took (read by the LOCALIZATION_DIAGNOSTICS output).
// g_distance_lookups: every distance read of this pixel's search (read by the probe: the same work per strategy).
int g_iterations_taken = 0;
int g_distance_lookups = 0;
#if defined(IMPOSTOR_LAYERS)
// IMPOSTOR_LAYERS: the search may run in a layer of a cube-map array instead (an effect's per-object distance maps,
// e.g. the inter-reflections'): g_impostor_layer ≥ 0 selects it, −1 (the default) reads u_env.
uniform samplerCubeArray u_impostor_layers;
int g_impostor_layer = -1;
#endif
float env_distance(vec3 direction) {
    ++g_distance_lookups;
#if defined(IMPOSTOR_LAYERS)
    if (g_impostor_layer >= 0) return textureLod(u_impostor_layers, vec4(direction, float(g_impostor_layer)), 0.0).a;
#endif
    return textureLod(u_env, direction, 0.0).a;
}
// ρ(p) = |p| / D(p/|p|): < 1 undershoot (in front of the environment), > 1 overshoot.
float impostor_rho(vec3 p) { return length(p) / env_distance(p); }
bool converged(float rho) { return abs(rho - 1.0) < float(TOLERANCE); }
// eq. 4.4: pair guess d (with ρ) with the point at infinity.
float pair_with_infinity(float d, float rho, float DR) { return max(d + DR * (1.0 - rho), 0.0); }
// eq. 4.6: the ray parameter where the line through (d_a, ρ_a), (d_b, ρ_b) reaches ρ = 1.
float refine(float d_a, float rho_a, float d_b, float rho_b) {
    float denominator = rho_b - rho_a;
    if (abs(denominator) < 1e-7) return d_b;
    return max(d_b + (d_b - d_a) * (1.0 - rho_b) / denominator, 0.0);
}

#if defined(STRATEGY_ILLINOIS) || defined(STRATEGY_SAFE_SECANT)
// The safeguarded root finders work on f(d) = ρ(x + R d) − 1 and keep a bracket: the latest undershoot a (f < 0)
// and overshoot b (f > 0) with a < b. Every new guess lies strictly inside it (b = ∞ until an overshoot is known:
// then the guess moves outwards by the sphere proxy, never by pairing with infinity), so d stays ≥ 0 and no two
// guesses collapse onto one point. The bracket starts at the shaded point d = 0 (an undershoot inside the room);
// the first guess is the perpendicular one (eq. 4.2).
// illinois: false position between a and b; when the same end is replaced twice in a row, the other end's f is
//   halved (the Illinois modification: superlinear, where plain regula falsi keeps one end fixed and crawls).
// safe-secant: the secant through the last two guesses (the first pair: the shaded point and the first guess); a step
//   that leaves the bracket or has a vanishing denominator is replaced by the bracket's midpoint (or by the
//   outward step while no overshoot is known).

// No overshoot known yet: from the undershoot a (f_a < 0) to where the ray leaves the sphere around o through the
// environment seen in a's direction, |x + R d| = D = |p_a| / ρ_a (the sphere proxy's closed form, exact in a
// sphere room). D > |p_a|, so the new guess lies beyond a (by at least 1e-4 D(R), should a sit on o itself).
float outwards(vec3 x, vec3 R, float a, float fa, float DR) {
    float D = length(x + R * a) / max(1.0 + fa, 1e-6);
    float xr = dot(x, R);
    return max(-xr + sqrt(max(xr * xr - dot(x, x) + D * D, 0.0)), a + 1e-4 * DR);
}

// The linear search (GPU Gems 3 ch. 17's approach, before the refinement): SEARCH_STEPS points along the ray,
// d_k = |x| t_k / (1 − t_k) with t_k = k / (SEARCH_STEPS + 1), i.e. p = (x (1 − t) + |x| R t) / (1 − t): the
// direction seen from o sweeps from x towards R in steps even in t, the cube map's own measure. It stops at the first
// undershoot → overshoot change, so the bracket holds the first crossing of ρ = 1 along the ray and the refinement
// cannot reach a later one (a later root is what a thin occluder or a ray passing a column otherwise converges to).
// A crossing narrower than a step can still be stepped over: the search finds the first crossing it sees.
float impostor_distance(vec3 x, vec3 R) {
    float DR = env_distance(R);
    const float infinity = 3.0e38;
    float a = 0.0, fa = impostor_rho(x) - 1.0;
    float b = infinity, fb = 0.0;
    bool has_a = fa < 0.0;
    if (!has_a) fa = 0.0;  // the shaded point lies behind the environment seen from o: no undershoot known yet
    int last_side = 0;     // -1: a was replaced last, +1: b
    // The best evaluated guess (smallest |f|): what is returned, so that one more step never moves the lookup to a
    // point farther from ρ = 1 than the last limit's (|ρ − 1| at the lookup does not grow with NITER).
    float best = 0.0, best_f = has_a ? -fa : infinity;
    bool evaluated = has_a;
    for (int k = 1; k <= SEARCH_STEPS; ++k) {
        float t = float(k) / float(SEARCH_STEPS + 1);
        float dk = length(x) * t / (1.0 - t);
        float f = impostor_rho(x + R * dk) - 1.0;
        if (abs(f) < best_f) {
            best = dk;
            best_f = abs(f);
            evaluated = true;
        }
        if (f < 0.0) {
            a = dk;
            fa = f;
            has_a = true;
        } else if (has_a) {
            b = dk;
            fb = f;
            break;
        }
    }
    // The first guess: inside a bracket false position; else the perpendicular one (eq. 4.2) when it lies beyond
    // the shaded point (and the search), else outwards.
    float perpendicular = DR - dot(x, R);
    float d = b < infinity ? a - fa * (b - a) / (fb - fa)
                           : (perpendicular > a ? perpendicular : (has_a ? outwards(x, R, a, fa, DR) : DR));
#if defined(STRATEGY_SAFE_SECANT)
    float d_prev = a, f_prev = fa;
    bool has_prev = has_a;
#endif
    for (int i = 0; i < NITER; ++i) {
        float f = impostor_rho(x + R * d) - 1.0;
        g_iterations_taken = i + 1;
        if (abs(f) < best_f) {
            best = d;
            best_f = abs(f);
            evaluated = true;
        }
        if (abs(f) < float(TOLERANCE)) return d;
        if (f < 0.0) {
            if (last_side == -1 && b < infinity) fb *= 0.5;
            a = d;
            fa = f;
            has_a = true;
            last_side = -1;
        } else {
            if (last_side == 1 && has_a) fa *= 0.5;
            b = d;
            fb = f;
            last_side = 1;
        }
#if defined(STRATEGY_SAFE_SECANT)
        float next = -1.0;
        if (has_prev && abs(f - f_prev) > 1e-12 * max(abs(f), abs(f_prev))) next = d - f * (d - d_prev) / (f - f_prev);
        d_prev = d;
        f_prev = f;
        has_prev = true;
        if (!(next > a && next < b)) {
            if (b < infinity) next = has_a ? 0.5 * (a + b) : 0.5 * b;
            else next = outwards(x, R, a, fa, DR);
        }
        d = next;
#else
        if (has_a && b < infinity) d = a - fa * (b - a) / (fb - fa);  // fa < 0 < fb: strictly inside (a, b)
        else if (has_a) d = outwards(x, R, a, fa, DR);  // no overshoot yet
        else d = 0.5 * b;  // only overshoots so far: towards the shaded point
#endif
    }
    // With no step taken the first guess goes unevaluated (the thesis's 0 iterations); otherwise the best evaluated
    // guess, never an unchecked one.
    return NITER == 0 || !evaluated ? d : best;
}
#else
// The thesis's three strategies, as described (Lazányi, ch. 4; docs/preview.md, "The technique").
float impostor_distance(vec3 x, vec3 R) {
    float DR = env_distance(R);
#if defined(STRATEGY_SECANT)
    // Start: the perpendicular-surface guess (eq. 4.2), then its pairing with infinity (eq. 4.4); each step pairs
    // the last two guesses (eq. 4.6).
    float d_prev = max(DR - dot(x, R), 0.0);
    float rho_prev = impostor_rho(x + R * d_prev);
    float d = pair_with_infinity(d_prev, rho_prev, DR);
    for (int i = 0; i < NITER; ++i) {
        float rho = impostor_rho(x + R * d);
        g_iterations_taken = i + 1;
        if (converged(rho)) break;
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
        g_iterations_taken = i;
        if (i > 0 && converged(rho)) break;
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
    return d;
}
#endif

vec3 reflection_lookup(vec3 x, vec3 R) { return x + R * impostor_distance(x, R); }
#endif
