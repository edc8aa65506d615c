#version 410 core
// Surface fragment shader: finds the exact surface point under the pixel (analytic sphere, or
// the interpolated point of a planar mesh), then sums f_r · E⊥ · cos θ over the lights.
// generated/material.glsl is made per model from its parameter table (MaterialParams,
// loadMaterialParams(), the model's GLSL twin and GLINT_EVAL_BRDF); the prelude defines
// GLINT_MSAA_SAMPLES when rendering multisampled.
#include "common/uniforms.glsl"
#include "common/frame.glsl"
#include "common/lights.glsl"
#include "generated/material.glsl"
#include "common/shading.glsl"

const int SHAPE_MESH = 0;
const int SHAPE_SPHERE = 1;

uniform int shapeKind;
uniform vec4 sphere;  // xyz: centre, w: radius
#ifdef GLINT_MSAA_SAMPLES
uniform vec2 sampleOffsets[GLINT_MSAA_SAMPLES];  // sample positions within the pixel, [0,1)²
#endif

in vec3 worldPosition;
in vec3 worldNormal;
in vec3 worldTangent;
out vec4 outRadiance;

// Nearest t > 0 with |o + t·d − c| = r, or -1.
float intersectSphere(Ray ray) {
    vec3 offset = ray.origin - sphere.xyz;
    float b = dot(offset, ray.direction);
    float c = dot(offset, offset) - sphere.w * sphere.w;
    float discriminant = b * b - c;
    if (discriminant < 0.0) return -1.0;
    float root = sqrt(discriminant);
    if (-b - root > 0.0) return -b - root;
    if (-b + root > 0.0) return -b + root;
    return -1.0;
}

// Twin of surfaceTangent() in core/render/reference_renderer.cpp for a sphere: the direction of
// increasing u, (+y) × n normalised, and the u = 0 meridian's tangent at the poles.
vec3 sphereTangent(vec3 outwardNormal) {
    vec3 alongU = vec3(outwardNormal.z, 0.0, -outwardNormal.x);
    float alongULength = length(alongU);
    return alongULength > 1e-6 ? alongU / alongULength : vec3(0.0, 0.0, -1.0);
}

void main() {
    Ray ray = primaryRay(gl_FragCoord.xy);
    vec3 position = worldPosition;
    vec3 normal = normalize(worldNormal);
    vec3 tangent = worldTangent;  // planes: the mesh tangent
    float depth = gl_FragCoord.z;
    if (shapeKind == SHAPE_SPHERE) {
        float t = intersectSphere(ray);
#ifdef GLINT_MSAA_SAMPLES
        // Coverage from the analytic silhouette, sample by sample.
        int mask = 0;
        for (int i = 0; i < GLINT_MSAA_SAMPLES; ++i) {
            Ray sampleRay = primaryRay(floor(gl_FragCoord.xy) + sampleOffsets[i]);
            float sampleT = intersectSphere(sampleRay);
            if (sampleT > 0.0) {
                mask |= 1 << i;
                if (t < 0.0) { ray = sampleRay; t = sampleT; }
            }
        }
        if (mask == 0) discard;
        gl_SampleMask[0] = mask;
#else
        if (t < 0.0) discard;
#endif
        position = ray.origin + t * ray.direction;
        normal = (position - sphere.xyz) / sphere.w;
        tangent = sphereTangent(normal);
        vec4 clip = viewProjection * vec4(position, 1.0);
        depth = 0.5 * (clip.z / clip.w) + 0.5;
    }
    if (dot(normal, ray.direction) > 0.0) normal = -normal;  // two-sided surfaces
    gl_FragDepth = depth;
    ShadingFrame frame = frameFromNormalAndTangent(normalize(normal), tangent);
    outRadiance = vec4(shadeSurface(position, frame, -ray.direction), 1.0);
}
