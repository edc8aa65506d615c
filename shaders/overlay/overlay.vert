#version 410 core
// Overlay vertex shader: hands world position and normal to the overlay geometry shaders
// (wireframe.geom, normals.geom). No shading.
#include "common/uniforms.glsl"

layout(location = 0) in vec3 inPosition;
layout(location = 1) in vec3 inNormal;

uniform vec4 placement;  // xyz: offset [m], w: uniform scale, as in surface.vert

out vec3 vertexPosition;
out vec3 vertexNormal;

void main() {
    vertexPosition = placement.xyz + placement.w * inPosition;
    vertexNormal = inNormal;
    gl_Position = viewProjection * vec4(vertexPosition, 1.0);
}
