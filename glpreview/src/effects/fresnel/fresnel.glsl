// The Fresnel of a sphere at μ = cos θ: FRESNEL_REFERENCE, the exact curve R_c(μ) from libfit as a 1D RGB texture;
// otherwise FRESNEL_CALL is a libfit model function (its GLSL is libfit's single definition, prepended) on its
// FRESNEL_PARAMETERS parameters (ShaderBuilder::fresnel_model).
#if defined(FRESNEL_REFERENCE)
uniform sampler1D u_fresnel_lut;  // texel i holds R_c(i / (n − 1))
vec3 fresnel(float mu) {
    float n = float(textureSize(u_fresnel_lut, 0));
    return textureLod(u_fresnel_lut, (mu * (n - 1.0) + 0.5) / n, 0.0).rgb;
}
#else
uniform vec3 u_param[FRESNEL_PARAMETERS];  // the model's parameters, one vec3 (R, G, B) each, in libfit's order
vec3 fresnel(float mu) { return FRESNEL_CALL; }
#endif
