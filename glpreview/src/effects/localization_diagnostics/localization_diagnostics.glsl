// Why the localization is where it is: the distance impostor's refinement steps taken (r) and |ρ − 1| at its lookup
// point (g); b = 1 marks the impostor's pixels; 0 for spheres that use no impostor.
vec3 localization_diagnostics(vec3 p, vec3 R) {
#if defined(REFLECTION_DISTANCE_IMPOSTOR)
    vec3 lookup = reflection_lookup(p - u_reference, R);
    return vec3(float(g_iterations_taken), abs(impostor_rho(lookup) - 1.0), 1.0);
#else
    return vec3(0.0);
#endif
}
