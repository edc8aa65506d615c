#version 410 core
// Surface vertex shader: world-space position, normal, tangent (along increasing u) and texture
// coordinates for the fragment stage.
#include "common/uniforms.glsl"

layout(location = 0) in vec3 inPosition;
layout(location = 1) in vec3 inNormal;
layout(location = 2) in vec3 inTangent;
layout(location = 3) in vec2 inUv;

out vec3 worldPosition;
out vec3 worldNormal;
out vec3 worldTangent;
out vec2 surfaceUv;

void main() {
    worldPosition = inPosition;
    worldNormal = inNormal;
    worldTangent = inTangent;
    surfaceUv = inUv;
    gl_Position = viewProjection * vec4(inPosition, 1.0);
}
