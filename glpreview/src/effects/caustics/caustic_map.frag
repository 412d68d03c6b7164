// One caustic map (the distance-impostor article's caustic generation; docs/preview.md, "Caustics"): each texel is a
// photon of one light aimed at one ring. It reflects off the ring's walls (analytic, with the ring's Fresnel at each
// reflection's μ, per RGB channel) until it leaves them, then finds where it lands with the distance-impostor search
// in the room's distance cube (u_env: the room without rings, the safeguarded root finder). Out: the receiver point
// and its room face (2·axis + side; −1: no photon), and the photon's power (W) after its reflections.
#define CAUSTIC_MAX_REFLECTIONS 4
uniform int u_map_size;
uniform int u_ring;          // the ring the photons are aimed at
uniform int u_caustic_kind;    // 0: parallel beam (directional), 1: a cap of directions from a point (point, spot)
uniform vec3 u_caustic_power_in;  // W/m² (beam) or W/sr (point, spot), colour included
// Beam: texel (u, v) ∈ [0, 1]² starts at u_beam_origin + u·u_beam_u + v·u_beam_v along u_caustic_direction.
uniform vec3 u_beam_origin;
uniform vec3 u_beam_u;
uniform vec3 u_beam_v;
uniform vec3 u_caustic_direction;  // unit: the beam's direction, or the spot's axis
// Cap: directions within acos(u_cap_cos) of u_cap_axis, even in solid angle; from u_caustic_position.
uniform vec3 u_caustic_position;
uniform vec3 u_cap_axis;
uniform float u_cap_cos;
uniform vec2 u_spot_cone;  // spot: cos of the outer and inner angles; (−2, −1): no cone
uniform vec3 u_room_min_c;
uniform vec3 u_room_max_c;
layout(location = 0) out vec4 out_hit;
layout(location = 1) out vec4 out_power;

void main() {
    out_hit = vec4(0.0, 0.0, 0.0, -1.0);
    out_power = vec4(0.0);
    vec2 uv = gl_FragCoord.xy / float(u_map_size);
    float photons = float(u_map_size * u_map_size);
    vec3 o, d;
    vec3 power;
    if (u_caustic_kind == 0) {
        o = u_beam_origin + uv.x * u_beam_u + uv.y * u_beam_v;
        d = u_caustic_direction;
        power = u_caustic_power_in * (length(u_beam_u) * length(u_beam_v) / photons);  // E × the texel's cross-section
    } else {
        float cos_t = 1.0 - uv.y * (1.0 - u_cap_cos), sin_t = sqrt(max(1.0 - cos_t * cos_t, 0.0));
        float phi = 6.28318530717959 * uv.x;
        vec3 w = u_cap_axis;
        vec3 a = normalize(abs(w.y) < 0.99 ? cross(w, vec3(0.0, 1.0, 0.0)) : cross(w, vec3(1.0, 0.0, 0.0)));
        vec3 b = cross(w, a);
        o = u_caustic_position;
        d = normalize(cos_t * w + sin_t * (cos(phi) * a + sin(phi) * b));
        float solid_angle = 6.28318530717959 * (1.0 - u_cap_cos) / photons;
        float cone = u_spot_cone.x < -1.0 ? 1.0 : smoothstep(u_spot_cone.x, u_spot_cone.y, dot(d, u_caustic_direction));
        power = u_caustic_power_in * (solid_angle * cone);
    }
    vec3 n;
    int which;
    if (rings_first(o, d, 0.0, 1e30, n, which) < 0.0 || which != u_ring) return;
    int reflections = 0;
    for (; reflections < CAUSTIC_MAX_REFLECTIONS; ++reflections) {
        float t = rings_first(o, d, reflections == 0 ? 0.0 : 1e-4, 1e30, n, which);
        if (t < 0.0) break;
        o += t * d;
        power *= ring_fresnel(which, clamp(-dot(d, n), 0.0, 1.0));
        d = reflect(d, n);
    }
    if (reflections == CAUSTIC_MAX_REFLECTIONS) return;  // still bouncing: dropped
    vec3 x = o - u_reference;
    vec3 p = u_reference + x + d * impostor_distance(x, d);
    // The room face it landed on: the nearest of the six planes, within 2 cm (else a box: no receiver).
    float best = 1e30;
    int face = -1;
    for (int axis = 0; axis < 3; ++axis) {
        float to_min = abs(p[axis] - u_room_min_c[axis]), to_max = abs(p[axis] - u_room_max_c[axis]);
        if (to_min < best) { best = to_min; face = 2 * axis; }
        if (to_max < best) { best = to_max; face = 2 * axis + 1; }
    }
    if (best > 0.02) return;
    out_hit = vec4(p, float(face));
    out_power = vec4(power, 1.0);
}
