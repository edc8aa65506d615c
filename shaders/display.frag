#version 410 core
// The display pass: the display chain (common/display_encode.glsl) applied to the radiance
// texture, into the 8-bit target or onto the screen. Headless renders without MSAA skip it: their
// radiance passes write the same encoding into a second target (common/display_output.glsl).
#include "common/display_encode.glsl"

uniform sampler2D radiance;   // linear float, same size as the output
uniform ivec2 sourceOffset;   // where the viewport's lower-left pixel reads from
uniform int pixelScale;       // screen pixels per radiance pixel along each axis (1 = full resolution)
uniform bool levelsRamp;      // bottom eighth: a grey radiance ramp 0..1 (display_chain.h levelsRampRadiance)

out vec4 outColor;

void main() {
    ivec2 pixel = (ivec2(gl_FragCoord.xy) - sourceOffset) / pixelScale;
    vec3 value = texelFetch(radiance, pixel, 0).rgb;
    ivec2 size = textureSize(radiance, 0);
    if (levelsRamp && pixel.y < max(1, size.y / 8)) value = vec3((float(pixel.x) + 0.5) / float(size.x));
    outColor = vec4(displayEncode(value, pixel), 1.0);
}
