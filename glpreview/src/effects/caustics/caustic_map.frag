// One caustic map (the distance-impostor article's caustic generation; docs/preview.md, "Caustics"): each texel is a
// photon of one light aimed at one ring; a sphere or room box between the light and the wall absorbs it. It reflects
// off the ring's walls (analytic, with the ring's Fresnel at each reflection's μ, per RGB channel) until it leaves
// them, then finds where it lands with the distance-impostor search in the room's distance cube (u_env: the room
// without rings, the safeguarded root finder); a sphere on the way there absorbs it. Out: the receiver point and its
// room face (2·axis + side; −1: no photon), and the photon's power (W) after its reflections.
#define CAUSTIC_MAX_REFLECTIONS 4
#define MAX_CAUSTIC_SPHERES 256
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
uniform int u_caustic_sphere_count;
uniform vec4 u_caustic_spheres[MAX_CAUSTIC_SPHERES];  // the scene's spheres: centre, radius
uniform vec3 u_room_min_c;
uniform vec3 u_room_max_c;
layout(location = 0) out vec4 out_hit;
layout(location = 1) out vec4 out_power;

// Whether a sphere or a room box lies on the ray o + t d within t_max (the photon's path to its ring, or from its last
// reflection to where it lands): the photon is absorbed, as the CPU reference's are.
bool caustic_blocked(vec3 o, vec3 d, float t_max) {
    for (int i = 0; i < u_caustic_sphere_count; ++i) {
        vec3 oc = o - u_caustic_spheres[i].xyz;
        float b = dot(oc, d);
        float h = b * b - (dot(oc, oc) - u_caustic_spheres[i].w * u_caustic_spheres[i].w);
        if (h < 0.0) continue;
        float t = -b - sqrt(h);
        if (t > 1e-4 && t < t_max) return true;
    }
    vec3 inv = vec3(1.0 / env_safe(d.x), 1.0 / env_safe(d.y), 1.0 / env_safe(d.z));
    for (int b = 0; b < u_box_count; ++b) {
        vec3 t1 = (u_box_min[b] - o) * inv, t2 = (u_box_max[b] - o) * inv;
        vec3 lo = min(t1, t2), hi = max(t1, t2);
        float t_near = max(lo.x, max(lo.y, lo.z)), t_far = min(hi.x, min(hi.y, hi.z));
        if (t_near <= t_far && t_near > 1e-4 && t_near < t_max) return true;
    }
    return false;
}

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
    float t_ring = rings_first(o, d, 0.0, 1e30, n, which);
    if (t_ring < 0.0 || which != u_ring) return;
    // Its shadow ray, from the wall back to the light (a directional light's: across the whole room).
    vec3 at = o + t_ring * d;
    if (caustic_blocked(at, -d, u_caustic_kind == 0 ? 1e30 : t_ring)) return;
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
    float landed = impostor_distance(x, d);
    vec3 p = u_reference + x + d * landed;
    if (caustic_blocked(o, d, landed)) return;  // a sphere (or a box) before the room: absorbed
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
