#version 410 core
// The background pass: the radiance of the constant or sky background, or of the environment
// when it is shown, along each pixel's primary ray, drawn after the objects where none wrote
// depth. Twin of the CPU reference's miss (MissRadiance::primary).
#include "common/uniforms.glsl"
#include "common/frame.glsl"
#include "common/background.glsl"
#include "common/environment.glsl"
#include "common/display_output.glsl"

void main() {
    writeRadiance(primaryMissRadiance(primaryRay(gl_FragCoord.xy).direction));
}
