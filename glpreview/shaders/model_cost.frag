// Shader cost of one Fresnel model: every pixel evaluates it EVALUATIONS times at different μ (FRESNEL_CALL is the
// libfit model function or the reference LUT lookup), summed so that nothing is optimised away.
uniform vec3 u_param[FRESNEL_PARAMETERS];  // the model's parameters (ShaderBuilder::fresnel_model)
uniform sampler1D u_fresnel_lut;
uniform vec2 u_viewport;
layout(location = 0) out vec4 out_color;

vec3 reference_lut(float mu) {
    float n = float(textureSize(u_fresnel_lut, 0));
    return textureLod(u_fresnel_lut, (mu * (n - 1.0) + 0.5) / n, 0.0).rgb;
}

void main() {
    float mu0 = gl_FragCoord.x / u_viewport.x;
    float step_mu = gl_FragCoord.y / (u_viewport.y * float(EVALUATIONS));
    vec3 sum = vec3(0.0);
    for (int i = 0; i < EVALUATIONS; ++i) {
        float mu = fract(mu0 + float(i) * step_mu);
        sum += FRESNEL_CALL;
    }
    out_color = vec4(sum, 1.0);
}
