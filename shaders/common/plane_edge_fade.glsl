// A plane's edge fade into the primary miss radiance; twin of core/scene/plane_edge_fade.h (the
// formula and its meaning there). Set per object by the renderer; radii (0, 0): no fade.

uniform vec3 fadeCenter;  // the plane's centre [m]
uniform vec2 fadeRadii;   // where the fade starts and ends [m]

vec3 fadeIntoBackground(vec3 radiance, vec3 position, vec3 rayDirection) {
    if (fadeRadii.y <= 0.0) return radiance;
    float t = clamp((length(position - fadeCenter) - fadeRadii.x) / max(fadeRadii.y - fadeRadii.x, 1e-6), 0.0, 1.0);
    return mix(radiance, primaryMissRadiance(rayDirection), t * t * (3.0 - 2.0 * t));
}
