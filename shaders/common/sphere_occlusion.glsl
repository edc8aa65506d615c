// Analytic occlusion of the environment light by the scene's spheres; twin of
// core/render/sphere_occlusion.h (the formula, its meaning and its limits there). Set per draw.

uniform vec4 occludingSpheres[8];  // xyz: centre [m], w: radius [m] (kMaxOccludingSpheres)
uniform int occludingSphereCount;

float environmentVisibility(vec3 position, vec3 normal) {
    float visibility = 1.0;
    for (int i = 0; i < occludingSphereCount; ++i) {
        vec4 sphere = occludingSpheres[i];
        vec3 toCentre = sphere.xyz - position;
        float distanceSquared = max(dot(toCentre, toCentre), sphere.w * sphere.w);
        float cosTheta = max(dot(normal, toCentre) * inversesqrt(distanceSquared), 0.0);
        visibility *= 1.0 - min(cosTheta * sphere.w * sphere.w / distanceSquared, 1.0);
    }
    return visibility;
}
