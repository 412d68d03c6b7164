#version 450 core
// A photon's Gaussian in a light map: its power × the normalised Gaussian of σ (cut at 3σ and renormalised), the
// irradiance it adds (W/m²) at each texel centre; blended additively.
uniform float u_sigma;
uniform vec2 u_texel_metres;
flat in vec3 v_power;
flat in vec2 v_centre;
layout(location = 0) out vec4 out_irradiance;

void main() {
    vec2 offset = (gl_FragCoord.xy - v_centre) * u_texel_metres;
    float r2 = dot(offset, offset), s2 = u_sigma * u_sigma;
    if (r2 > 9.0 * s2) discard;
    float kernel = exp(-0.5 * r2 / s2) / (6.28318530717959 * s2 * (1.0 - exp(-4.5)));
    out_irradiance = vec4(v_power * kernel, 0.0);
}
