// The captured cube (radiance, distance in alpha) downsampled to M × M texels per face, thesis ch. 5 (István Zsolt
// Lazányi, "Efficient Rendering of Realistic Metals", 2008; FORMULAS.md §6): output texel (face · M + i, j) of a
// 6M × M target averages the source texels it covers — their radiance (out_radiance) and their position relative
// to the reference point, direction × distance (out_position). Each becomes one area light of the localized sum.
uniform samplerCube u_env;  // the captured cube, level 0
uniform int u_source_size;  // S, the source's texels per edge (a multiple of M is not needed: texel ranges round)
uniform int u_m;
layout(location = 0) out vec4 out_radiance;
layout(location = 1) out vec4 out_position;

void main() {
    ivec2 texel = ivec2(gl_FragCoord.xy);
    int face = texel.x / u_m;
    int i = texel.x - face * u_m, j = texel.y;
    int x0 = i * u_source_size / u_m, x1 = (i + 1) * u_source_size / u_m;
    int y0 = j * u_source_size / u_m, y1 = (j + 1) * u_source_size / u_m;
    vec3 radiance = vec3(0.0), position = vec3(0.0);
    for (int y = y0; y < y1; ++y)
        for (int x = x0; x < x1; ++x) {
            vec2 st = 2.0 * (vec2(x, y) + 0.5) / float(u_source_size) - 1.0;
            vec3 d = normalize(cube_direction(face, st.x, st.y));
            vec4 texel_value = textureLod(u_env, d, 0.0);  // the texel centre: its own value
            radiance += texel_value.rgb;
            position += d * texel_value.a;
        }
    float n = float((x1 - x0) * (y1 - y0));
    out_radiance = vec4(radiance / n, 1.0);
    out_position = vec4(position / n, 1.0);
}
