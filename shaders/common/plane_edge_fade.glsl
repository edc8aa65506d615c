// A plane's edge fade into the primary miss radiance; twin of core/scene/plane_edge_fade.h (the
// formula and its meaning there). Compiled in for a plane with a fade (GLINT_PLANE_EDGE_FADE,
// gl/surface_variant.h) only: llvmpipe would run it for every pixel of every object behind an if.

#ifdef GLINT_PLANE_EDGE_FADE
uniform vec3 fadeCenter;  // the plane's centre [m]
uniform vec2 fadeRadii;   // where the fade starts and ends [m]

vec3 fadeIntoBackground(vec3 radiance, vec3 position, vec3 rayDirection) {
    float t = clamp((length(position - fadeCenter) - fadeRadii.x) / max(fadeRadii.y - fadeRadii.x, 1e-6), 0.0, 1.0);
    return mix(radiance, primaryMissRadiance(rayDirection), t * t * (3.0 - 2.0 * t));
}
#else
vec3 fadeIntoBackground(vec3 radiance, vec3 position, vec3 rayDirection) { return radiance; }
#endif
