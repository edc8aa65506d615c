#version 410 core
// Overlay lines drawn over the displayed image: a line fragment shows only where it is not behind
// the shaded surface. The surface depth comes from the radiance pass (a texture, possibly at a
// coarser preview resolution), so both depths are turned into distances along the pixel's ray
// and compared with a relative tolerance. Colours are display values (no exposure, no tone map).
#include "common/uniforms.glsl"

uniform sampler2D sceneDepth;  // window depth of the radiance pass
uniform ivec2 viewportOrigin;  // lower-left of the displayed image in window pixels
uniform int pixelScale;        // window pixels per radiance pixel
uniform vec4 overlayColor;     // display-encoded RGBA

out vec4 outColor;

// Distance from the near plane along the pixel's ray to the point at window depth `depth`.
float distanceAlongRay(vec2 ndc, float depth) {
    vec4 nearPoint = inverseViewProjection * vec4(ndc, -1.0, 1.0);
    vec4 point = inverseViewProjection * vec4(ndc, 2.0 * depth - 1.0, 1.0);
    return length(point.xyz / point.w - nearPoint.xyz / nearPoint.w);
}

void main() {
    vec2 local = gl_FragCoord.xy - vec2(viewportOrigin);
    ivec2 texel = ivec2(floor(local / float(pixelScale)));
    float storedDepth = texelFetch(sceneDepth, texel, 0).r;
    vec2 ndc = 2.0 * local / (viewportSize.xy * float(pixelScale)) - 1.0;
    float surfaceDistance = distanceAlongRay(ndc, storedDepth);
    float lineDistance = distanceAlongRay(ndc, gl_FragCoord.z);
    if (storedDepth < 1.0 && lineDistance > surfaceDistance * 1.01 + 1e-3) discard;
    outColor = overlayColor;
}
