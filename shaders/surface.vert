#version 410 core
// Surface vertex shader: world-space position and normal for the fragment stage.
#include "common/uniforms.glsl"

layout(location = 0) in vec3 inPosition;
layout(location = 1) in vec3 inNormal;

out vec3 worldPosition;
out vec3 worldNormal;

void main() {
    worldPosition = inPosition;
    worldNormal = inNormal;
    gl_Position = viewProjection * vec4(inPosition, 1.0);
}
