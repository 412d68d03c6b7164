// GGX prefiltering of the captured cube u_env into one face of one mip level of the prefiltered cube: each texel
// direction N (taken as the view and mirror direction, N = V = R: the split-sum approximation) integrates the
// environment over the GGX lobe of roughness u_roughness (α = roughness²), weighted by n·l, with filtered importance
// sampling (Jaroslav Křivánek, Mark Colbert, "Real-time Shading with Filtered Importance Sampling", 2008): u_samples
// Hammersley half vectors, each read from the source mip level whose texel matches the sample's solid angle.
// Roughness 0 copies the source along N.
uniform samplerCube u_env;  // the captured cube with its mip chain
uniform int u_face;         // 0..5: +X, −X, +Y, −Y, +Z, −Z
uniform int u_size;         // this level's texels per edge
uniform int u_source_size;  // the source's level-0 texels per edge
uniform float u_roughness;
uniform int u_samples;
layout(location = 0) out vec4 out_texel;

const float PI = 3.14159265358979;

vec2 hammersley(uint i, uint n) {
    return vec2((float(i) + 0.5) / float(n), float(bitfieldReverse(i)) * 2.3283064365386963e-10);
}

void main() {
    vec2 st = 2.0 * gl_FragCoord.xy / float(u_size) - 1.0;
    vec3 N = normalize(cube_direction(u_face, st.x, st.y));
    float alpha = u_roughness * u_roughness;
    if (alpha == 0.0) {
        out_texel = vec4(textureLod(u_env, N, 0.0).rgb, 1.0);
        return;
    }
    // An orthonormal frame around N (Duff et al. 2017).
    float sign_z = N.z >= 0.0 ? 1.0 : -1.0;
    float a = -1.0 / (sign_z + N.z);
    float b = N.x * N.y * a;
    vec3 T = vec3(1.0 + sign_z * N.x * N.x * a, sign_z * b, -sign_z * N.x);
    vec3 B = vec3(b, sign_z + N.y * N.y * a, -N.y);
    float a2 = alpha * alpha;
    float texel_solid_angle = 4.0 * PI / (6.0 * float(u_source_size) * float(u_source_size));
    vec3 sum = vec3(0.0);
    float weight = 0.0;
    for (int i = 0; i < u_samples; ++i) {
        vec2 u = hammersley(uint(i), uint(u_samples));
        float cos_h = sqrt((1.0 - u.x) / (1.0 + (a2 - 1.0) * u.x));
        float sin_h = sqrt(max(0.0, 1.0 - cos_h * cos_h));
        float phi = 2.0 * PI * u.y;
        vec3 H = T * (sin_h * cos(phi)) + B * (sin_h * sin(phi)) + N * cos_h;
        vec3 L = 2.0 * dot(N, H) * H - N;
        float n_l = dot(N, L);
        if (n_l <= 0.0) continue;
        float d = cos_h * cos_h * (a2 - 1.0) + 1.0;
        float D = a2 / (PI * d * d);
        float pdf = D / 4.0;  // D(h) (n·h) / (4 v·h) with v = n
        float sample_solid_angle = 1.0 / (float(u_samples) * pdf);
        float lod = max(0.5 * log2(sample_solid_angle / texel_solid_angle) + 1.0, 0.0);
        sum += textureLod(u_env, L, lod).rgb * n_l;
        weight += n_l;
    }
    out_texel = vec4(sum / max(weight, 1e-20), 1.0);
}
