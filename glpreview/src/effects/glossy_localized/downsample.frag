// The captured cube (radiance, distance in alpha) downsampled to M × M texels per face, thesis ch. 5 (István Zsolt
// Lazányi, "Efficient Rendering of Realistic Metals", 2008; docs/scene.md, "Rough spheres (exact rules)"): output texel (face · M + i, j) of a
// 6M × M target averages the source texels it covers — their radiance (out_radiance) and their position relative
// to the reference point, direction × distance (out_position.xyz). Each becomes one area light of the localized sum;
// out_position.a is its solid angle from the reference point, Δω_i (the rectangle below).
// The light is the face rectangle [−1 + 2i/M, −1 + 2(i + 1)/M] × [−1 + 2j/M, −1 + 2(j + 1)/M] that the localized sum
// takes its solid angle of: a source texel on its border (S not a multiple of M) counts with the fraction of it
// that lies inside, so that the averages describe exactly that rectangle.
uniform samplerCube u_env;  // the captured cube, level 0
uniform int u_source_size;  // S, the source's texels per edge
uniform int u_m;
layout(location = 0) out vec4 out_radiance;
layout(location = 1) out vec4 out_position;

// The overlap of source texel [k, k + 1] with [a, b] (source texel units).
float coverage(int k, float a, float b) { return max(min(float(k + 1), b) - max(float(k), a), 0.0); }

void main() {
    ivec2 texel = ivec2(gl_FragCoord.xy);
    int face = texel.x / u_m;
    int i = texel.x - face * u_m, j = texel.y;
    float scale = float(u_source_size) / float(u_m);
    float u0 = float(i) * scale, u1 = float(i + 1) * scale, v0 = float(j) * scale, v1 = float(j + 1) * scale;
    int x0 = int(floor(u0)), x1 = int(ceil(u1)), y0 = int(floor(v0)), y1 = int(ceil(v1));
    vec3 radiance = vec3(0.0), position = vec3(0.0);
    float n = 0.0;
    for (int y = y0; y < y1; ++y)
        for (int x = x0; x < x1; ++x) {
            float w = coverage(x, u0, u1) * coverage(y, v0, v1);
            if (w <= 0.0) continue;
            vec2 st = 2.0 * (vec2(x, y) + 0.5) / float(u_source_size) - 1.0;
            vec3 d = normalize(cube_direction(face, st.x, st.y));
            vec4 texel_value = textureLod(u_env, d, 0.0);  // the texel centre: its own value
            radiance += w * texel_value.rgb;
            position += w * d * texel_value.a;
            n += w;
        }
    out_radiance = vec4(radiance / n, 1.0);
    float step_st = 2.0 / float(u_m);
    float s0 = -1.0 + float(i) * step_st, t0 = -1.0 + float(j) * step_st;
    out_position = vec4(position / n, face_rectangle_solid_angle(s0, s0 + step_st, t0, t0 + step_st));
}
