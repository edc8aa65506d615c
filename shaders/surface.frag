#version 410 core
// Surface fragment shader: finds the exact surface point under the pixel (analytic sphere, or
// the interpolated point of a triangle mesh with its interpolated (Phong) or face (flat) normal),
// then shades it (common/shading.glsl), fading a plane's edge (common/plane_edge_fade.glsl): the lights, the ambient light and the traced delta lobes
// of mirror and glass. With GLINT_GOURAUD it outputs the radiance interpolated between vertices.
// Only with GLINT_RAY_CAST_SPHERE (an exact sphere's program, gl/surface_variant.h) does it write
// gl_FragDepth: a triangle's depth is the rasterizer's, tested before the shader runs.
// generated/material.glsl is made per model from its parameter table (MaterialParams,
// loadMaterialParams(), the model's GLSL twin and GLINT_EVAL_BRDF); the prelude defines
// GLINT_MSAA_SAMPLES when rendering multisampled.
#include "common/uniforms.glsl"
#include "common/frame.glsl"
#include "common/lights.glsl"
#include "common/background.glsl"
#include "common/environment.glsl"
#include "common/shape.glsl"
#include "common/specular_transport.glsl"
#include "generated/material.glsl"
#include "common/shading.glsl"
#include "common/plane_edge_fade.glsl"
#include "common/display_output.glsl"

#ifdef GLINT_MSAA_SAMPLES
uniform vec2 sampleOffsets[GLINT_MSAA_SAMPLES];  // sample positions within the pixel, [0,1)²
#endif

in vec3 worldPosition;
in vec3 worldNormal;
in vec3 worldTangent;
in vec2 surfaceUv;
#ifdef GLINT_GOURAUD
in vec3 vertexRadiance;
#endif
uniform int flatNormals;  // 1: flat interpolation, the triangle's own normal

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
    vec3 tangent = worldTangent;  // meshes: the interpolated tangent
    // The plane of the triangle from the position's screen-space derivatives (exact for a
    // linearly interpolated attribute); its orientation does not matter (two-sided, below).
    vec3 faceNormal = cross(dFdx(worldPosition), dFdy(worldPosition));
    if (flatNormals == 1 && dot(faceNormal, faceNormal) > 0.0) normal = normalize(faceNormal);
#ifdef GLINT_RAY_CAST_SPHERE
    {  // the exact sphere inside its proxy: this program draws nothing else
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
        gl_FragDepth = 0.5 * (clip.z / clip.w) + 0.5;
    }
#endif
#ifdef GLINT_TEXTURED
    // Textures (common/textures.glsl): the sphere's exact (u, v), the mesh's interpolated UV.
    vec2 uv = shapeKind == SHAPE_SPHERE ? sphereUv(normal) : surfaceUv;
    textureCoordinates = textureCoordinatesAt(uv, position - objectCenter);
#endif
    if (dot(normal, ray.direction) > 0.0) normal = -normal;  // two-sided surfaces
#ifdef GLINT_GOURAUD
    writeRadiance(fadeIntoBackground(vertexRadiance, position, ray.direction));
    return;
#endif
    ShadingFrame frame = frameFromNormalAndTangent(normalize(normal), tangent);
    // Twin of normalMappedFrame in core/texture/texture_eval.cpp: both maps read in this frame.
#ifdef GLINT_COAT_NORMAL_SLOT
    vec3 coatNormal = normalMappedFrame(GLINT_COAT_NORMAL_SLOT, frame).normal;
#endif
#ifdef GLINT_NORMAL_MAP_SLOT
    frame = normalMappedFrame(GLINT_NORMAL_MAP_SLOT, frame);
#endif
#ifdef GLINT_COAT_NORMAL_SLOT
    frame.coatNormal = coatNormal;
#endif
    writeRadiance(fadeIntoBackground(shadeSurface(position, frame, -ray.direction), position, ray.direction));
}
