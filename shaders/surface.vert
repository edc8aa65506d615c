#version 410 core
// Surface vertex shader: world-space position (the object's placement applied), normal and
// tangent (along increasing u) for the fragment stage. With GLINT_GOURAUD it also shades the
// vertex (shadeSurface(), the lecture's Gouraud shading) for the rasterizer to interpolate.
#include "common/uniforms.glsl"
#ifdef GLINT_GOURAUD
#include "common/frame.glsl"
#include "common/lights.glsl"
#include "common/background.glsl"
#include "common/shape.glsl"
#include "common/specular_transport.glsl"
#include "generated/material.glsl"
#include "common/shading.glsl"
out vec3 vertexRadiance;  // W/(sr·m²)
#endif

layout(location = 0) in vec3 inPosition;
layout(location = 1) in vec3 inNormal;
layout(location = 2) in vec3 inTangent;

uniform vec4 placement;  // xyz: offset [m], w: uniform scale (imported meshes; else 0, 0, 0, 1)

out vec3 worldPosition;
out vec3 worldNormal;
out vec3 worldTangent;

void main() {
    worldPosition = placement.xyz + placement.w * inPosition;
    worldNormal = inNormal;
    worldTangent = inTangent;
    gl_Position = viewProjection * vec4(worldPosition, 1.0);
#ifdef GLINT_GOURAUD
    // Twin of gouraudRadiance() in core/render/triangle_shading.cpp: the vertex normal turned
    // towards the viewer (two-sided surfaces), shaded as a pixel would be.
    vec3 towardsViewer = towardsViewerFrom(worldPosition);
    vec3 normal = normalize(inNormal);
    if (dot(normal, towardsViewer) < 0.0) normal = -normal;
    vertexRadiance = shadeSurface(worldPosition, frameFromNormalAndTangent(normal, inTangent), towardsViewer);
#endif
}
