// The GGX lobe the rough spheres' GLSL shares (the localized sum, the lights' highlights), as docs/scene.md's rough
// spheres' rules define it: Smith's Λ and f_r cos θ_l without the Fresnel, D G2 / (4 n·v), height-correlated G2.
const float GGX_PI = 3.14159265358979;
float ggx_smith_lambda(float cos_t, float a2) {
    float c2 = max(cos_t * cos_t, 1e-12);
    return 0.5 * (-1.0 + sqrt(1.0 + a2 * (1.0 - c2) / c2));
}
// f_r cos θ_i for light direction l and half vector H, without the Fresnel: D G2 / (4 n·v); lambda_v = Λ(v).
float ggx_lobe(vec3 N, vec3 H, vec3 l, float a2, float lambda_v, float n_v) {
    float n_h = dot(N, H);
    float d = n_h * n_h * (a2 - 1.0) + 1.0;
    float D = a2 / (GGX_PI * d * d);
    float G2 = 1.0 / (1.0 + lambda_v + ggx_smith_lambda(dot(N, l), a2));
    return D * G2 / (4.0 * n_v);
}
