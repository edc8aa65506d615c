#version 410 core
// The display pass: the display chain (common/display_encode.glsl) applied to the radiance
// texture, into the 8-bit target or onto the screen. Headless renders without MSAA skip it: their
// radiance passes write the same encoding into a second target (common/display_output.glsl).
#include "common/display_encode.glsl"

uniform sampler2D radiance;   // linear float, same size as the output
uniform ivec2 sourceOffset;   // where the viewport's lower-left pixel reads from
uniform int pixelScale;       // screen pixels per radiance pixel along each axis (1 = full resolution)

out vec4 outColor;

void main() {
    vec3 value = texelFetch(radiance, (ivec2(gl_FragCoord.xy) - sourceOffset) / pixelScale, 0).rgb;
    outColor = vec4(displayEncode(value), 1.0);
}
