// The scene's lights (lights effect): their light on the room's surfaces (ENVIRONMENT_LIGHTING), sphere lights as
// emitters seen by camera and mirror rays (REFLECTED_EMITTER) and the direct specular of rough spheres
// (lights_specular: GGX D·G2 with the sphere's Fresnel at v·h), each shadowed through its distance map with
// percentage-closer soft shadows (PCSS, Fernando 2005: a blocker search, then a filter as wide as the penumbra the
// light's size and the blocker's distance give). docs/preview.md, "Lights".
#define MAX_LIGHTS 8
const float LIGHTS_PI = 3.14159265358979;
uniform int u_light_count;
uniform int u_light_type[MAX_LIGHTS];        // 0 point, 1 spot, 2 directional, 3 sphere
uniform vec3 u_light_position[MAX_LIGHTS];
uniform vec3 u_light_direction[MAX_LIGHTS];  // unit: where a spot points, where directional light travels
uniform vec3 u_light_power[MAX_LIGHTS];      // colour × intensity: I (W/sr), E (W/m²) or L (W/(m² sr))
uniform float u_light_radius[MAX_LIGHTS];    // sphere lights
uniform vec2 u_light_cone[MAX_LIGHTS];       // spot: cos of the outer and inner angles
uniform int u_light_shadow[MAX_LIGHTS];      // its layer among the cube maps (local) or planes (directional); −1: none
uniform vec3 u_shadow_plane_origin[MAX_LIGHTS];
uniform vec3 u_shadow_plane_u[MAX_LIGHTS];
uniform vec3 u_shadow_plane_v[MAX_LIGHTS];
uniform samplerCubeArray u_shadow_cubes;  // distance from the light to the first occluder along each direction
uniform sampler2DArray u_shadow_planes;   // distance along the light from the plane to the first occluder

// The Vogel disc: sample k of n in the unit disc.
vec2 lights_disc(int k, int n) {
    float r = sqrt((float(k) + 0.5) / float(n));
    float phi = float(k) * 2.39996323;
    return r * vec2(cos(phi), sin(phi));
}

const int LIGHTS_SHADOW_SAMPLES = 16;

// The fraction of the light that reaches p, from a local light's distance cube map. `slope`: tan of the angle between
// the receiver's normal and the light: the depth bias grows with the width each sample looks across times it, so
// that a surface lit at a grazing angle does not shadow itself.
float lights_shadow_cube(int i, int layer, vec3 p, float slope) {
    vec3 to = p - u_light_position[i];
    float z = length(to);
    vec3 w = to / z;
    vec3 t1 = normalize(abs(w.y) < 0.99 ? cross(w, vec3(0.0, 1.0, 0.0)) : cross(w, vec3(1.0, 0.0, 0.0)));
    vec3 t2 = cross(w, t1);
    float bias = 0.01 + 0.002 * z;
    float texel = 2.0 / float(textureSize(u_shadow_cubes, 0).x);  // a texel's angle near a face's centre
    float r = u_light_radius[i];
    // Blocker search: occluders between a quarter of the way and p hide part of the light from p.
    float search = max(3.0 * r / z, 1.5 * texel);
    float blockers = 0.0, blocker_z = 0.0;
    for (int k = 0; k < LIGHTS_SHADOW_SAMPLES; ++k) {
        vec2 o = search * lights_disc(k, LIGHTS_SHADOW_SAMPLES);
        float d = texture(u_shadow_cubes, vec4(normalize(w + o.x * t1 + o.y * t2), float(layer))).r;
        if (d < z - bias - z * length(o) * slope) {
            blockers += 1.0;
            blocker_z += d;
        }
    }
    if (blockers == 0.0) return 1.0;
    blocker_z /= blockers;
    // The penumbra's angular radius seen from the light: r (z − z_b) / (z_b z); at least a texel and a half.
    float filter_radius = max(r * (z - blocker_z) / (blocker_z * z), 1.5 * texel);
    float lit = 0.0;
    for (int k = 0; k < LIGHTS_SHADOW_SAMPLES; ++k) {
        vec2 o = filter_radius * lights_disc(k, LIGHTS_SHADOW_SAMPLES);
        float d = texture(u_shadow_cubes, vec4(normalize(w + o.x * t1 + o.y * t2), float(layer))).r;
        lit += d >= z - bias - z * length(o) * slope ? 1.0 : 0.0;
    }
    return lit / float(LIGHTS_SHADOW_SAMPLES);
}

// The same from a directional light's plane (a light without size: a filter of a texel and a half).
float lights_shadow_plane(int i, int layer, vec3 p, float slope) {
    vec3 rel = p - u_shadow_plane_origin[i];
    vec3 U = u_shadow_plane_u[i], V = u_shadow_plane_v[i];
    vec2 uv = vec2(dot(rel, U) / dot(U, U), dot(rel, V) / dot(V, V));
    float z = dot(rel, u_light_direction[i]);
    float bias = 0.01 + 0.002 * z;
    vec2 texel = vec2(1.0) / vec2(textureSize(u_shadow_planes, 0).xy);
    float lit = 0.0;
    for (int k = 0; k < LIGHTS_SHADOW_SAMPLES; ++k) {
        vec2 o = 1.5 * texel * lights_disc(k, LIGHTS_SHADOW_SAMPLES);
        float across = length(o.x * U + o.y * V);  // how far the sample looks from p, in the room
        lit += texture(u_shadow_planes, vec3(uv + o, float(layer))).r >= z - bias - across * slope ? 1.0 : 0.0;
    }
    return lit / float(LIGHTS_SHADOW_SAMPLES);
}

// The fraction of light i that reaches p (unit normal n). The receiver is moved along its normal by a texel of the
// map at its distance, so that an occluder's own surface (a box face, a sphere) does not shadow itself.
float lights_shadow(int i, vec3 p, vec3 n) {
    int layer = u_light_shadow[i];
    if (layer < 0) return 1.0;
    vec3 l = u_light_type[i] == 2 ? -u_light_direction[i] : normalize(u_light_position[i] - p);
    float n_l = clamp(dot(n, l), 0.05, 1.0);
    float slope = min(sqrt(1.0 - n_l * n_l) / n_l, 10.0);
    if (u_light_type[i] == 2) {
        float texel = max(length(u_shadow_plane_u[i]), length(u_shadow_plane_v[i])) / float(textureSize(u_shadow_planes, 0).x);
        return lights_shadow_plane(i, layer, p + texel * n, slope);
    }
    float texel = 2.0 * length(p - u_light_position[i]) / float(textureSize(u_shadow_cubes, 0).x);
    return lights_shadow_cube(i, layer, p + texel * n, slope);
}

// Light i at p: the unit direction l towards it, its irradiance E normal to l (unshadowed) and its distance.
void lights_at(int i, vec3 p, out vec3 l, out vec3 E, out float dist) {
    int type = u_light_type[i];
    if (type == 2) {
        l = -u_light_direction[i];
        E = u_light_power[i];
        dist = 1e30;
        return;
    }
    vec3 to = u_light_position[i] - p;
    float d2 = dot(to, to);
    dist = sqrt(d2);
    l = to / dist;
    if (type == 3) {  // a uniform sphere: as a point of its power at its centre (exact above the horizon)
        float r = u_light_radius[i];
        E = u_light_power[i] * (LIGHTS_PI * r * r / d2);
        return;
    }
    E = u_light_power[i] / d2;
    if (type == 1) E *= smoothstep(u_light_cone[i].x, u_light_cone[i].y, dot(-l, u_light_direction[i]));
}

// Radiance a Lambertian room surface of `albedo` at p (inward normal n) reflects of the lights.
vec3 lights_on_surface(vec3 albedo, vec3 p, vec3 n) {
    vec3 sum = vec3(0.0);
    for (int i = 0; i < u_light_count; ++i) {
        vec3 l, E;
        float dist;
        lights_at(i, p, l, E, dist);
        float n_l = dot(n, l);
        if (n_l <= 0.0) continue;
        sum += E * (n_l * lights_shadow(i, p, n));
    }
    return albedo / LIGHTS_PI * sum;
}

// The nearest sphere light a ray from o along unit d meets: its radiance in `emitted`.
bool lights_emitter(vec3 o, vec3 d, out vec3 emitted) {
    float best = 1e30;
    bool hit = false;
    emitted = vec3(0.0);
    for (int i = 0; i < u_light_count; ++i) {
        if (u_light_type[i] != 3) continue;
        vec3 oc = o - u_light_position[i];
        float b = dot(oc, d);
        float h = b * b - (dot(oc, oc) - u_light_radius[i] * u_light_radius[i]);
        if (h < 0.0) continue;
        float t = -b - sqrt(h);
        if (t > 0.0 && t < best) {
            best = t;
            emitted = u_light_power[i];
            hit = true;
        }
    }
    return hit;
}
