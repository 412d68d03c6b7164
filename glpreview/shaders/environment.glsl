// The environment, traced analytically on the GPU (capture of the cube map, background of the camera view).
// Mirrors src/environment.cpp line by line; exactly one of ENV_ROOM, ENV_SPHERE_ROOM, ENV_EQUIRECT (at infinity),
// ENV_EQUIRECT_BOX, ENV_EQUIRECT_SPHERE (the image on its proxy) is defined.
#define MAX_BOXES 32
#define MAX_PANELS 16

uniform vec3 u_reference;  // the reference point o (cube map centre)

#if defined(ENV_ROOM)
uniform vec3 u_room_min;
uniform vec3 u_room_max;
uniform vec3 u_wall_x_min;
uniform vec3 u_wall_x_max;
uniform vec3 u_wall_z_min;
uniform vec3 u_wall_z_max;
uniform vec3 u_floor_light;
uniform vec3 u_floor_dark;
uniform vec3 u_ceiling;
uniform float u_checker;
uniform int u_panel_count;
uniform vec4 u_panel_rect[MAX_PANELS];  // min x, min z, max x, max z
uniform vec3 u_panel_radiance[MAX_PANELS];
uniform int u_box_count;
uniform vec3 u_box_min[MAX_BOXES];
uniform vec3 u_box_max[MAX_BOXES];
uniform vec3 u_box_color[MAX_BOXES];

float env_safe(float d) { return abs(d) < 1e-12 ? (d < 0.0 ? -1e-12 : 1e-12) : d; }

bool checker_even(float a, float b, float size) {
    return ((int(floor(a / size)) + int(floor(b / size))) & 1) == 0;
}

// A room surface of colour c (its radiance) at p with inward normal n: where an effect lights the room
// (ENVIRONMENT_LIGHTING(albedo, p, n): the lights; ENVIRONMENT_CAUSTICS(albedo, p, n): light that objects threw onto
// it; ENVIRONMENT_INDIRECT(albedo, p, n): light the room reflected once more; each its reflected radiance), that light
// added with the albedo c clamped to 1.
#if defined(ENVIRONMENT_CAUSTICS) || defined(ENVIRONMENT_INDIRECT)
vec3 lit_surface(vec3 c, vec3 p, vec3 n) {
    vec3 albedo = min(c, vec3(1.0));
    vec3 radiance = c;
#if defined(ENVIRONMENT_LIGHTING)
    radiance += ENVIRONMENT_LIGHTING(albedo, p, n);
#endif
#if defined(ENVIRONMENT_CAUSTICS)
    radiance += ENVIRONMENT_CAUSTICS(albedo, p, n);
#endif
#if defined(ENVIRONMENT_INDIRECT)
    radiance += ENVIRONMENT_INDIRECT(albedo, p, n);
#endif
    return radiance;
}
#define ROOM_SURFACE(c, p, n) lit_surface(c, p, n)
#elif defined(ENVIRONMENT_LIGHTING)
vec3 lit_surface(vec3 c, vec3 p, vec3 n) { return c + ENVIRONMENT_LIGHTING(min(c, vec3(1.0)), p, n); }
#define ROOM_SURFACE(c, p, n) lit_surface(c, p, n)
#else
#define ROOM_SURFACE(c, p, n) (c)
#endif

// rgb: radiance, a: ray parameter of the hit. The room's walls, floor, ceiling and boxes.
vec4 room_trace(vec3 o, vec3 d) {
    vec3 inv = vec3(1.0 / env_safe(d.x), 1.0 / env_safe(d.y), 1.0 / env_safe(d.z));
    float t_best = 1e30;
    int axis = 0;
    for (int i = 0; i < 3; ++i) {
        float t = ((inv[i] > 0.0 ? u_room_max[i] : u_room_min[i]) - o[i]) * inv[i];
        if (t < t_best) {
            t_best = t;
            axis = i;
        }
    }
    bool positive_side = inv[axis] > 0.0;
    int box_hit = -1;
    int box_axis = 0;
    for (int b = 0; b < u_box_count; ++b) {
        float t_near = -1e30, t_far = 1e30;
        int near_axis = 0;
        for (int i = 0; i < 3; ++i) {
            float t1 = (u_box_min[b][i] - o[i]) * inv[i], t2 = (u_box_max[b][i] - o[i]) * inv[i];
            float lo = min(t1, t2), hi = max(t1, t2);
            if (lo > t_near) {
                t_near = lo;
                near_axis = i;
            }
            t_far = min(t_far, hi);
        }
        if (t_near <= t_far && t_near > 0.0 && t_near < t_best) {
            t_best = t_near;
            box_hit = b;
            box_axis = near_axis;
        }
    }
    vec3 p = o + t_best * d;
    if (box_hit >= 0) {
        float shade = box_axis == 1 ? 1.0 : box_axis == 0 ? 0.7 : 0.85;
        vec3 n = vec3(0.0);
        n[box_axis] = d[box_axis] > 0.0 ? -1.0 : 1.0;  // the face the ray entered
        return vec4(ROOM_SURFACE(shade * u_box_color[box_hit], p, n), t_best);
    }
    vec3 n = vec3(0.0);
    n[axis] = positive_side ? -1.0 : 1.0;  // the wall's inward normal
    if (axis == 1) {
        if (!positive_side) return vec4(ROOM_SURFACE(checker_even(p.x, p.z, u_checker) ? u_floor_light : u_floor_dark, p, n), t_best);
        for (int i = 0; i < u_panel_count; ++i) {
            vec4 r = u_panel_rect[i];
            if (p.x >= r.x && p.x <= r.z && p.z >= r.y && p.z <= r.w) return vec4(u_panel_radiance[i], t_best);  // emitters
        }
        return vec4(ROOM_SURFACE(u_ceiling, p, n), t_best);
    }
    if (axis == 0) {
        float shade = checker_even(p.z, p.y, u_checker) ? 1.0 : 0.75;
        return vec4(ROOM_SURFACE(shade * (positive_side ? u_wall_x_max : u_wall_x_min), p, n), t_best);
    }
    float shade = checker_even(p.x, p.y, u_checker) ? 1.0 : 0.75;
    return vec4(ROOM_SURFACE(shade * (positive_side ? u_wall_z_max : u_wall_z_min), p, n), t_best);
}

// The room and the objects effects stand in it (ENVIRONMENT_OBJECT(o, d, t_max, out seen): whether the ray meets one
// before t_max, and its radiance and ray parameter; ROOM_ONLY leaves them out).
#if defined(ENVIRONMENT_OBJECT) && !defined(ROOM_ONLY)
vec4 environment_trace(vec3 o, vec3 d) {
    vec4 room = room_trace(o, d);
    vec4 seen;
    return ENVIRONMENT_OBJECT(o, d, room.a, seen) ? seen : room;
}
#else
vec4 environment_trace(vec3 o, vec3 d) { return room_trace(o, d); }
#endif

#elif defined(ENV_SPHERE_ROOM)
uniform float u_sphere_room_radius;
uniform float u_sphere_room_checker;  // degrees
uniform vec3 u_sphere_room_light;
uniform vec3 u_sphere_room_dark;

bool checker_even(float a, float b, float size) {
    return ((int(floor(a / size)) + int(floor(b / size))) & 1) == 0;
}

vec4 environment_trace(vec3 origin, vec3 d) {
    vec3 p = origin - u_reference;
    float b = dot(p, d), c = dot(p, p) - u_sphere_room_radius * u_sphere_room_radius;
    float t = -b + sqrt(max(b * b - c, 0.0));
    vec3 u = normalize(p + t * d);
    float lat = degrees(asin(clamp(u.y, -1.0, 1.0)));
    float lon = degrees(atan(u.z, u.x));
    return vec4(checker_even(lat, lon, u_sphere_room_checker) ? u_sphere_room_light : u_sphere_room_dark, t);
}

#elif defined(ENV_EQUIRECT) || defined(ENV_EQUIRECT_BOX) || defined(ENV_EQUIRECT_SPHERE)
uniform sampler2D u_equirect;  // RGB32F, row 0 at the top (v = 0: +y)
uniform float u_equirect_intensity;

// Bilinear with texelFetch (u wraps, v clamps), as sample_equirect() in C++: no filtering-hardware rounding.
vec3 sample_equirect(vec3 d) {
    ivec2 size = textureSize(u_equirect, 0);
    float u = 0.5 + atan(d.x, -d.z) / (2.0 * 3.14159265358979);
    float v = acos(clamp(d.y, -1.0, 1.0)) / 3.14159265358979;
    float x = u * float(size.x) - 0.5, y = v * float(size.y) - 0.5;
    float x0 = floor(x), y0 = floor(y);
    float fx = x - x0, fy = y - y0;
    int ix = int(x0);  // in [-1, width - 1]: wrap by hand (GLSL's % is undefined for negative operands)
    int xa = ix < 0 ? ix + size.x : ix, xb = ix + 1 >= size.x ? ix + 1 - size.x : ix + 1;
    int ya = clamp(int(y0), 0, size.y - 1), yb = clamp(int(y0) + 1, 0, size.y - 1);
    vec3 top = (1.0 - fx) * texelFetch(u_equirect, ivec2(xa, ya), 0).rgb + fx * texelFetch(u_equirect, ivec2(xb, ya), 0).rgb;
    vec3 bottom = (1.0 - fx) * texelFetch(u_equirect, ivec2(xa, yb), 0).rgb + fx * texelFetch(u_equirect, ivec2(xb, yb), 0).rgb;
    return (1.0 - fy) * top + fy * bottom;
}

#if defined(ENV_EQUIRECT_BOX)
// The image painted on the proxy box: the ray leaves the box at t, the image is read in the direction from the
// capture point o to that point.
uniform vec3 u_proxy_min;  // the proxy box relative to o
uniform vec3 u_proxy_max;
float proxy_safe(float d) { return abs(d) < 1e-12 ? (d < 0.0 ? -1e-12 : 1e-12) : d; }
vec4 environment_trace(vec3 origin, vec3 d) {
    vec3 x = origin - u_reference;
    vec3 inv = vec3(1.0 / proxy_safe(d.x), 1.0 / proxy_safe(d.y), 1.0 / proxy_safe(d.z));
    vec3 t3 = max((u_proxy_max - x) * inv, (u_proxy_min - x) * inv);
    float t = min(t3.x, min(t3.y, t3.z));
    return vec4(u_equirect_intensity * sample_equirect(normalize(x + t * d)), t);
}
#elif defined(ENV_EQUIRECT_SPHERE)
// The image painted on the proxy sphere of radius u_proxy_radius around the capture point o.
uniform float u_proxy_radius;
vec4 environment_trace(vec3 origin, vec3 d) {
    vec3 x = origin - u_reference;
    float b = dot(x, d), c = dot(x, x) - u_proxy_radius * u_proxy_radius;
    float t = -b + sqrt(max(b * b - c, 0.0));
    return vec4(u_equirect_intensity * sample_equirect(normalize(x + t * d)), t);
}
#else
vec4 environment_trace(vec3 origin, vec3 d) { return vec4(u_equirect_intensity * sample_equirect(d), 1e30); }
#endif
#endif
