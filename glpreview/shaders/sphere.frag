// One sphere: ray-cast against the sphere and write the radiance of its lobe, SPHERE_RADIANCE, an expression the
// effects choose (ShaderBuilder::radiance; by default the mirror's below), plus SPHERE_ADDED_RADIANCE where effects
// add terms. The effects' GLSL (the Fresnel, the reflection lookup, the glossy lobes) comes before this file.
uniform vec3 u_sphere_center;
uniform float u_sphere_radius;
layout(location = 0) out vec4 out_color;

// The mirror: the reflected radiance (reflection_lookup into the captured cube map, or the image at infinity)
// times the Fresnel of μ = cos θ.
vec3 mirror_radiance(vec3 p, vec3 R, float mu) {
#if defined(REFLECTED_EMITTER)
    vec3 emitted;  // an emitter an effect puts in the room (a sphere light): seen before the environment
    if (REFLECTED_EMITTER(p, R, emitted)) return fresnel(mu) * emitted;
#endif
#if defined(ENV_EQUIRECT)
    vec3 L = environment_trace(p, R).rgb;  // at infinity: the direction alone
#elif defined(MIRROR_REFLECTED)
    vec3 L = MIRROR_REFLECTED(p, R);  // an effect follows the reflected ray further (inter-reflections)
#else
    vec3 L = textureLod(u_env, reflection_lookup(p - u_reference, R), 0.0).rgb;
#endif
    return fresnel(mu) * L;
}

void main() {
    vec3 d = camera_ray(gl_FragCoord.xy);
    vec3 oc = u_camera_position - u_sphere_center;
    float b = dot(oc, d);
    float h = b * b - (dot(oc, oc) - u_sphere_radius * u_sphere_radius);
    if (h < 0.0) discard;
    float t = -b - sqrt(h);
    if (t <= 0.0) discard;
    vec3 p = u_camera_position + t * d;
    vec3 N = (p - u_sphere_center) / u_sphere_radius;
    float mu = clamp(-dot(d, N), 0.0, 1.0);
    vec3 R = reflect(d, N);
    vec3 radiance = SPHERE_RADIANCE;
#if defined(SPHERE_ADDED_RADIANCE)
    radiance += SPHERE_ADDED_RADIANCE;
#endif
    out_color = vec4(radiance, t);  // a: the distance along the ray (a sphere drawn into another one's distance map)
    gl_FragDepth = t / (t + 1.0);
}
