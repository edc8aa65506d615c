#version 410 core
// The textbook floor of `glint bench` (core/gl/textbook_floor_pass.h): the cheapest correct
// program for the picture, written by hand as a textbook (or three.js's MeshStandardMaterial and
// MeshLambertMaterial) would write it, with none of Glint's code: the target is cleared to the
// background colour, then a square around the sphere (textbook_floor.vert) casts each pixel's ray
// at the sphere, shades a hit with the material and the scene's point and directional lights
// (their counts compile-time constants, as three.js does) and writes the sRGB-encoded 8-bit
// value; a miss is discarded. No float image, no depth.
// The prelude defines NUM_DIRECTIONAL, NUM_POINT and one of LAMBERT or GGX.

uniform vec3 eye;            // camera position [m]
uniform mat3 cameraBasis;    // columns: right, up, backward (world)
uniform vec2 tanHalfFov;     // tan of the half field of view, horizontally and vertically
uniform vec2 viewportSize;   // pixels
uniform vec4 sphere;         // xyz: centre [m], w: radius [m]
uniform vec3 ambient;        // ambient radiance [W/(sr·m²)]
uniform vec3 albedo;         // diffuse albedo
#ifdef GGX
uniform vec3 f0;             // Schlick's reflectance at normal incidence
uniform float alpha;         // GGX roughness α
#endif
#if NUM_DIRECTIONAL > 0
uniform vec3 directionalTowards[NUM_DIRECTIONAL];  // unit, towards the light
uniform vec3 directionalIrradiance[NUM_DIRECTIONAL];  // E⊥ [W/m²]
#endif
#if NUM_POINT > 0
uniform vec3 pointPosition[NUM_POINT];   // [m]
uniform vec3 pointIntensity[NUM_POINT];  // I [W/sr]
#endif

out vec4 outColor;

const float PI = 3.14159265358979;

// f_r · cos θ_i for one light direction l (unit) and view direction v (unit).
vec3 reflected(vec3 n, vec3 v, vec3 l) {
    float nl = dot(n, l);
    if (nl <= 0.0) return vec3(0.0);
    vec3 brdf = albedo / PI;
#ifdef GGX
    // Cook-Torrance: GGX distribution, height-correlated Smith visibility (Heitz 2014), Schlick.
    float nv = max(dot(n, v), 1e-4);
    vec3 h = normalize(l + v);
    float nh = max(dot(n, h), 0.0);
    float a2 = alpha * alpha;
    float d = nh * nh * (a2 - 1.0) + 1.0;
    float distribution = a2 / (PI * d * d);
    float visibility = 0.5 / (nl * sqrt(nv * nv * (1.0 - a2) + a2) + nv * sqrt(nl * nl * (1.0 - a2) + a2));
    float m = 1.0 - max(dot(v, h), 0.0);
    vec3 fresnel = f0 + (1.0 - f0) * (m * m * m * m * m);
    brdf += fresnel * (distribution * visibility);
#endif
    return brdf * nl;
}

vec3 srgb(vec3 linear) {
    vec3 c = clamp(linear, 0.0, 1.0);
    return mix(1.055 * pow(c, vec3(1.0 / 2.4)) - 0.055, 12.92 * c, lessThanEqual(c, vec3(0.0031308)));
}

void main() {
    vec2 ndc = 2.0 * gl_FragCoord.xy / viewportSize - 1.0;
    vec3 direction = normalize(cameraBasis * vec3(ndc * tanHalfFov, -1.0));
    vec3 offset = eye - sphere.xyz;
    float b = dot(offset, direction);
    float discriminant = b * b - dot(offset, offset) + sphere.w * sphere.w;
    if (discriminant < 0.0) discard;
    vec3 position = eye + (-b - sqrt(discriminant)) * direction;
    vec3 n = (position - sphere.xyz) / sphere.w;
    vec3 v = -direction;
    vec3 radiance = albedo * ambient;
#if NUM_DIRECTIONAL > 0
    for (int i = 0; i < NUM_DIRECTIONAL; ++i) radiance += reflected(n, v, directionalTowards[i]) * directionalIrradiance[i];
#endif
#if NUM_POINT > 0
    for (int i = 0; i < NUM_POINT; ++i) {
        vec3 toLight = pointPosition[i] - position;
        float distance2 = dot(toLight, toLight);
        radiance += reflected(n, v, toLight * inversesqrt(distance2)) * (pointIntensity[i] / distance2);
    }
#endif
    outColor = vec4(srgb(radiance), 1.0);
}
