// A rough sphere, split sum: the prefiltered radiance along the localized mirror lookup, at the mip level of its
// roughness, times the DFG table of this sphere's own Fresnel over (μ, roughness).
uniform samplerCube u_prefiltered;
uniform sampler2D u_dfg;  // texel (i, j): μ = i / (width − 1), roughness = j / (height − 1)
uniform float u_roughness;
uniform float u_prefiltered_levels;
vec3 dfg(float mu, float roughness) {
    vec2 size = vec2(textureSize(u_dfg, 0));
    return textureLod(u_dfg, (vec2(mu, roughness) * (size - 1.0) + 0.5) / size, 0.0).rgb;
}
// Where u_env and u_prefiltered were taken from: the environment's reference point, unless an effect binds a map of
// the sphere's own (GLOSSY_OWN_MAP: the inter-reflections', taken from u_glossy_origin, the sphere's centre).
#if defined(GLOSSY_OWN_MAP)
uniform vec3 u_glossy_origin;
#define GLOSSY_ORIGIN u_glossy_origin
#else
#define GLOSSY_ORIGIN u_reference
#endif
// The radiance of the rough sphere at p (world space) with mirror direction R.
vec3 prefiltered_glossy(vec3 p, vec3 R, float mu) {
    vec3 glossy = textureLod(u_prefiltered, reflection_lookup(p - GLOSSY_ORIGIN, R), u_roughness * (u_prefiltered_levels - 1.0)).rgb;
    return dfg(mu, u_roughness) * glossy;
}
