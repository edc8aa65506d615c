#version 410 core
// The background pass: the radiance of the constant or sky background along each pixel's
// primary ray, drawn after the objects where none wrote depth. Twin of the CPU reference's miss.
#include "common/uniforms.glsl"
#include "common/frame.glsl"
#include "common/background.glsl"
#include "common/display_output.glsl"

void main() {
    writeRadiance(backgroundRadiance(primaryRay(gl_FragCoord.xy).direction));
}
