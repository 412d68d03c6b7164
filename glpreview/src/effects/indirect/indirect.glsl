// The room's indirect light from virtual light sources (indirect effect; Lazányi's thesis, ch. 6; docs/preview.md,
// "Indirect light: virtual light sources"). ENVIRONMENT_INDIRECT (indirect_on_surface) reads it from the room faces'
// light maps; indirect_gather, run once per light-map texel (indirect_gather.frag), adds the light of every
// virtual light facing the point, each sample's potential contribution computed first without visibility, shadow rays traced
// only for the largest ones, which together hold u_indirect_rate of the point's total (the thesis's priority scheme
// and its evaluation rate; the cut-off found by bisection instead of sorting), the sum scaled by the total over the
// tested ones. gather_virtual_lights() and evaluation_cutoff() in virtual_lights.cpp are the same on the CPU.
#define MAX_VIRTUAL_LIGHTS 8192
#define MAX_INDIRECT_SPHERES 256
#define MAX_INDIRECT_BOXES 32
uniform sampler2D u_virtual_lights;  // column i: row 0 position, row 1 normal, row 2 intensity (W/sr)
uniform int u_virtual_light_count;
uniform float u_indirect_clamp;      // m
uniform float u_indirect_rate;
uniform int u_indirect_sphere_count;
uniform vec4 u_indirect_spheres[MAX_INDIRECT_SPHERES];  // centre, radius
uniform int u_indirect_box_count;
uniform vec3 u_indirect_box_min[MAX_INDIRECT_BOXES];
uniform vec3 u_indirect_box_max[MAX_INDIRECT_BOXES];
uniform sampler2DArray u_indirect_light;  // per room face (room_face.glsl): the gathered radiance per unit albedo
uniform vec3 u_indirect_room_min;
uniform vec3 u_indirect_room_max;

bool indirect_blocked(vec3 p, vec3 q) {
    vec3 v = q - p;
    float t_max = length(v) - 1e-4;
    vec3 d = v / length(v);
    for (int i = 0; i < u_indirect_sphere_count; ++i) {
        vec3 oc = p - u_indirect_spheres[i].xyz;
        float b = dot(oc, d);
        float h = b * b - (dot(oc, oc) - u_indirect_spheres[i].w * u_indirect_spheres[i].w);
        if (h < 0.0) continue;
        float t = -b - sqrt(h);
        if (t > 1e-4 && t < t_max) return true;
    }
    vec3 inv = vec3(1.0) / vec3(abs(d.x) < 1e-12 ? (d.x < 0.0 ? -1e-12 : 1e-12) : d.x,
                                abs(d.y) < 1e-12 ? (d.y < 0.0 ? -1e-12 : 1e-12) : d.y,
                                abs(d.z) < 1e-12 ? (d.z < 0.0 ? -1e-12 : 1e-12) : d.z);
    for (int b = 0; b < u_indirect_box_count; ++b) {
        vec3 t1 = (u_indirect_box_min[b] - p) * inv, t2 = (u_indirect_box_max[b] - p) * inv;
        vec3 lo = min(t1, t2), hi = max(t1, t2);
        float t_near = max(lo.x, max(lo.y, lo.z)), t_far = min(hi.x, min(hi.y, hi.z));
        if (t_near <= t_far && t_near > 1e-4 && t_near < t_max) return true;
    }
#if defined(ENVIRONMENT_OCCLUDER)
    vec3 n_ring;
    int which;
    if (rings_first(p, d, 1e-6, t_max, n_ring, which) > 0.0) return true;
#endif
    return false;
}

// The potential contribution of virtual light i at p (normal n): I cos θ_y cos θ_x / max(d², clamp²); 0 if either
// side faces away.
vec3 indirect_potential(int i, vec3 p, vec3 n) {
    vec3 v = texelFetch(u_virtual_lights, ivec2(i, 0), 0).xyz - p;
    float d2 = dot(v, v);
    if (!(d2 > 0.0)) return vec3(0.0);
    vec3 dir = v * inversesqrt(d2);
    float cos_x = dot(n, dir), cos_y = -dot(texelFetch(u_virtual_lights, ivec2(i, 1), 0).xyz, dir);
    if (cos_x <= 0.0 || cos_y <= 0.0) return vec3(0.0);
    return texelFetch(u_virtual_lights, ivec2(i, 2), 0).rgb * (cos_x * cos_y / max(d2, u_indirect_clamp * u_indirect_clamp));
}

// The reflected radiance of virtual lights at p per unit albedo: the priority scheme's gather.
vec3 indirect_gather(vec3 p, vec3 n) {
    float w[MAX_VIRTUAL_LIGHTS];
    float total = 0.0, hi = 0.0;
    int count = min(u_virtual_light_count, MAX_VIRTUAL_LIGHTS);
    for (int i = 0; i < count; ++i) {
        vec3 c = indirect_potential(i, p, n);
        w[i] = (c.r + c.g + c.b) / 3.0;
        total += w[i];
        hi = max(hi, w[i]);
    }
    if (!(total > 0.0)) return vec3(0.0);
    // The largest cut-off c whose samples (potential ≥ c) hold the evaluation rate of the total: bisection.
    float lo = 0.0;
    for (int step = 0; step < 24 && u_indirect_rate < 1.0; ++step) {
        float cut = 0.5 * (lo + hi), held = 0.0;
        for (int i = 0; i < count; ++i)
            if (w[i] >= cut) held += w[i];
        if (held >= u_indirect_rate * total) lo = cut; else hi = cut;
    }
    vec3 sum = vec3(0.0);
    float tested = 0.0;
    for (int i = 0; i < count; ++i) {
        if (!(w[i] > 0.0) || w[i] < lo) continue;
        tested += w[i];
        if (!indirect_blocked(p, texelFetch(u_virtual_lights, ivec2(i, 0), 0).xyz)) sum += indirect_potential(i, p, n);
    }
    return tested > 0.0 ? sum * (total / tested) / 3.14159265358979 : vec3(0.0);
}

vec3 indirect_on_surface(vec3 albedo, vec3 p, vec3 n) {
    int face;
    vec2 uv;
    if (!room_face_of(p, n, u_indirect_room_min, u_indirect_room_max, face, uv)) return vec3(0.0);
    return albedo * texture(u_indirect_light, vec3(uv, float(face))).rgb;
}
