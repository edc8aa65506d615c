#version 410 core
// Normals overlay: a line from each vertex of each drawn triangle along its vertex normal
// (vertices shared by several triangles draw the same line again).
#include "common/uniforms.glsl"

layout(triangles) in;
layout(line_strip, max_vertices = 6) out;

in vec3 vertexPosition[];
in vec3 vertexNormal[];
uniform float normalLength;  // [m]

void main() {
    for (int i = 0; i < 3; ++i) {
        gl_Position = gl_in[i].gl_Position;
        EmitVertex();
        gl_Position = viewProjection * vec4(vertexPosition[i] + normalLength * normalize(vertexNormal[i]), 1.0);
        EmitVertex();
        EndPrimitive();
    }
}
