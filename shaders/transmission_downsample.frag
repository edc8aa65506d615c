#version 410 core
// One level of the transmission backdrop's mip chain (core/gl/transmission_pass.cpp): each texel
// (premultiplied radiance, coverage) the mean of its 2×2 texels one level up, clamped at an odd edge. CPU twin: the chain built in
// core/render/transmission_backdrop.cpp.
uniform sampler2D source;  // the level above, bound as the texture's only level
out vec4 mean;

void main() {
    ivec2 size = textureSize(source, 0);
    ivec2 low = min(2 * ivec2(gl_FragCoord.xy), size - 1), high = min(2 * ivec2(gl_FragCoord.xy) + 1, size - 1);
    mean = 0.25 * (texelFetch(source, ivec2(low.x, low.y), 0) + texelFetch(source, ivec2(high.x, low.y), 0) +
                   texelFetch(source, ivec2(low.x, high.y), 0) + texelFetch(source, ivec2(high.x, high.y), 0));
}
