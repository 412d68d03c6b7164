// The scene's rings (rings effect; docs/scene.md, "Rings"): vertical cylinder walls of zero thickness, mirrors on
// both sides, drawn into every program that reads the environment. ENVIRONMENT_OBJECT (rings_seen): a ray that meets
// a wall before the room sees the room reflected in it, times the ring's Fresnel, one reflection (the reflected ray
// reads the room alone); ENVIRONMENT_OCCLUDER (rings_distance): where a shadow ray meets the first wall. The
// intersection repeats intersect_ring() of ring.cpp line by line.
#define MAX_RINGS 4
uniform int u_ring_count;
uniform vec3 u_ring_base[MAX_RINGS];     // the centre of the bottom circle
uniform vec4 u_ring_shape[MAX_RINGS];    // radius, height, cos and sin of the arc's middle azimuth
uniform float u_ring_cos_half_arc[MAX_RINGS];  // cos(arc / 2); ≤ −1: the whole circle
uniform sampler2D u_ring_fresnel;        // row i: ring i's F(μ) at μ_k = k / (width − 1), linear between them

vec4 room_trace(vec3 o, vec3 d);  // environment.glsl: the room without the rings

bool ring_covers(int i, vec2 offset) {
    if (u_ring_cos_half_arc[i] <= -1.0) return true;
    float r = length(offset);
    if (!(r > 0.0)) return false;
    return dot(offset, u_ring_shape[i].zw) / r >= u_ring_cos_half_arc[i];
}

// The ray parameter of ring i's first wall with t_min < t < t_max, or −1; n: the wall's unit normal facing the ray.
float ring_intersect(int i, vec3 o, vec3 d, float t_min, float t_max, out vec3 n) {
    n = vec3(0.0);
    float radius = u_ring_shape[i].x;
    vec2 oc = o.xz - u_ring_base[i].xz;
    float a = dot(d.xz, d.xz);
    if (!(a > 1e-18)) return -1.0;
    float b = dot(oc, d.xz);
    float h = b * b - a * (dot(oc, oc) - radius * radius);
    if (h < 0.0) return -1.0;
    float root = sqrt(h);
    for (int k = 0; k < 2; ++k) {
        float t = (-b + (k == 0 ? -root : root)) / a;
        if (!(t > t_min && t < t_max)) continue;
        vec3 p = o + t * d;
        if (p.y < u_ring_base[i].y || p.y > u_ring_base[i].y + u_ring_shape[i].y) continue;
        vec2 offset = p.xz - u_ring_base[i].xz;
        if (!ring_covers(i, offset)) continue;
        vec3 outward = vec3(offset.x / radius, 0.0, offset.y / radius);
        n = dot(d, outward) > 0.0 ? -outward : outward;
        return t;
    }
    return -1.0;
}

// The first wall of any ring: its t (−1: none), normal and ring.
float rings_first(vec3 o, vec3 d, float t_min, float t_max, out vec3 n, out int which) {
    float best = -1.0;
    which = -1;
    n = vec3(0.0);
    for (int i = 0; i < u_ring_count; ++i) {
        vec3 ni;
        float t = ring_intersect(i, o, d, t_min, best > 0.0 ? best : t_max, ni);
        if (t > 0.0) {
            best = t;
            n = ni;
            which = i;
        }
    }
    return best;
}

vec3 ring_fresnel(int i, float mu) {
    vec2 size = vec2(textureSize(u_ring_fresnel, 0));
    return texture(u_ring_fresnel, vec2((clamp(mu, 0.0, 1.0) * (size.x - 1.0) + 0.5) / size.x, (float(i) + 0.5) / size.y)).rgb;
}

bool rings_seen(vec3 o, vec3 d, float t_max, out vec4 seen) {
    seen = vec4(0.0);
    vec3 n;
    int which;
    float t = rings_first(o, d, 0.0, t_max, n, which);
    if (t < 0.0) return false;
    vec3 p = o + t * d;
    float mu = clamp(-dot(d, n), 0.0, 1.0);
    seen = vec4(ring_fresnel(which, mu) * room_trace(p, reflect(d, n)).rgb, t);
    return true;
}

float rings_distance(vec3 o, vec3 d) {
    vec3 n;
    int which;
    float t = rings_first(o, d, 0.0, 1e30, n, which);
    return t < 0.0 ? 1e30 : t;
}
