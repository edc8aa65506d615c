// Specular transport of mirror and glass, traced analytically: GLSL twin of
// core/render/specular_transport.h (see there for the physics and the limits: reflected rays
// see the environment or the background, transmitted rays the frame's opaque objects where the
// backdrop shows them). Needs environment.glsl.
#include "brdf/fresnel.glsl"
#include "common/transmission_backdrop.glsl"

const int MAX_INTERNAL_BOUNCES = 6;  // kMaxInternalBounces

vec3 reflectDirection(vec3 incoming, vec3 normal) {
    return incoming - 2.0 * dot(incoming, normal) * normal;
}

vec3 refractDirection(vec3 incoming, vec3 normal, float etaRatio) {
    float cosIncident = -dot(incoming, normal);
    float sin2Transmitted = etaRatio * etaRatio * (1.0 - cosIncident * cosIncident);
    float cosTransmitted = sqrt(max(0.0, 1.0 - sin2Transmitted));
    return etaRatio * incoming + (etaRatio * cosIncident - cosTransmitted) * normal;
}

float sphereExitDistance(vec4 sphereGeometry, vec3 origin, vec3 direction) {
    vec3 offset = origin - sphereGeometry.xyz;
    float b = dot(offset, direction);
    vec3 perpendicular = offset - b * direction;
    return -b + sqrt(max(0.0, sphereGeometry.w * sphereGeometry.w - dot(perpendicular, perpendicular)));
}

vec3 traceMirror(vec3 eta, vec3 kappa, vec3 normal, vec3 towardsViewer) {
    float cosOut = dot(normal, towardsViewer);
    return fresnelConductor(cosOut, eta, kappa) * missRadiance(reflectDirection(-towardsViewer, normal));
}

float glassReflectance(bool classic, float transmission, float cosIncident, float eta) {
    float fresnel = fresnelDielectric(cosIncident, eta);
    if (!classic || fresnel >= 1.0) return fresnel;
    return 1.0 - transmission;
}

// A ray inside the glass sphere at the wall point `origin` (see traceInsideSphere in the twin).
vec3 traceInsideSphere(float ior, bool classic, float transmission, vec3 absorption, vec4 sphereGeometry,
                       vec3 origin, vec3 direction, vec3 throughput, vec3 viewDirection) {
    vec3 radiance = vec3(0.0);
    for (int bounce = 0; bounce < MAX_INTERNAL_BOUNCES; ++bounce) {
        vec3 inwardNormal = (sphereGeometry.xyz - origin) / sphereGeometry.w;
        float exitReflectance = glassReflectance(classic, transmission, -dot(direction, inwardNormal), 1.0 / ior);
        if (exitReflectance < 1.0) {
            vec3 leaving = refractDirection(direction, inwardNormal, ior);
            vec3 seen = missRadiance(leaving);  // the first exit: the backdrop over it (traced once)
            if (bounce == 0) seen = throughBackdrop(origin, leaving, viewDirection, 0.0, seen);
            radiance += throughput * ((1.0 - exitReflectance) / (ior * ior)) * seen;
        }
        throughput *= exitReflectance;
        direction = reflectDirection(direction, inwardNormal);
        float chord = sphereExitDistance(sphereGeometry, origin, direction);
        origin += chord * direction;
        throughput *= exp(-absorption * chord);  // Beer-Lambert
    }
    return radiance;
}

// isSphere false: a thin pane (see the C++ twin); a viewer inside the sphere starts at the wall.
vec3 traceGlass(float ior, bool classic, float transmission, vec3 absorption, bool isSphere, vec4 sphereGeometry,
                vec3 position, vec3 normal, vec3 towardsViewer, float viewerDistance) {
    vec3 incoming = -towardsViewer;
    if (isSphere && dot(normal, position - sphereGeometry.xyz) < 0.0)
        return traceInsideSphere(ior, classic, transmission, absorption, sphereGeometry, position, incoming,
                                 exp(-absorption * viewerDistance), incoming);
    float entryReflectance = glassReflectance(classic, transmission, dot(normal, towardsViewer), ior);
    vec3 radiance = entryReflectance * missRadiance(reflectDirection(incoming, normal));
    if (!isSphere) {
        float paneTransmittance = (1.0 - entryReflectance) * (1.0 - entryReflectance);
        return radiance + paneTransmittance * transmittedRadiance(position, incoming, incoming);
    }
    vec3 refracted = refractDirection(incoming, normal, 1.0 / ior);
    float chord = sphereExitDistance(sphereGeometry, position, refracted);
    vec3 throughput = (1.0 - entryReflectance) * ior * ior * exp(-absorption * chord);
    return radiance + traceInsideSphere(ior, classic, transmission, absorption, sphereGeometry,
                                        position + chord * refracted, refracted, throughput, incoming);
}
