#version 450 core
// The splat of a caustic map into one room face's light map (docs/preview.md, "Caustics"): one point per caustic-map
// texel (gl_VertexID), placed at its receiver point in the face's (u, v), as large as its Gaussian's 3σ; photons of
// other faces are put outside the viewport.
uniform sampler2D u_caustic_hits;
uniform sampler2D u_caustic_power;
uniform int u_map_size;
uniform int u_face;
uniform vec3 u_face_origin;  // the face's corner at (u, v) = (0, 0)
uniform vec3 u_face_u;       // the face's u axis over its length: u = dot(p − origin, u_face_u) / |u_face_u|²
uniform vec3 u_face_v;
uniform float u_sigma;             // m
uniform vec2 u_texel_metres;       // a light-map texel's size (m) along u and v
uniform float u_max_point_size;
flat out vec3 v_power;
flat out vec2 v_centre;  // the photon's point in the light map, in texels

void main() {
    ivec2 t = ivec2(gl_VertexID % u_map_size, gl_VertexID / u_map_size);
    vec4 hit = texelFetch(u_caustic_hits, t, 0);
    v_power = texelFetch(u_caustic_power, t, 0).rgb;
    if (int(hit.w) != u_face) {
        gl_Position = vec4(4.0, 4.0, 0.0, 1.0);
        gl_PointSize = 1.0;
        v_centre = vec2(-1e9);
        return;
    }
    vec2 uv = vec2(dot(hit.xyz - u_face_origin, u_face_u) / dot(u_face_u, u_face_u),
                   dot(hit.xyz - u_face_origin, u_face_v) / dot(u_face_v, u_face_v));
    vec2 size = vec2(length(u_face_u), length(u_face_v)) / u_texel_metres;
    v_centre = uv * size;
    gl_Position = vec4(2.0 * uv - 1.0, 0.0, 1.0);
    float reach = 3.0 * u_sigma / min(u_texel_metres.x, u_texel_metres.y);
    gl_PointSize = min(2.0 * ceil(reach) + 3.0, u_max_point_size);
}
