// Screen-space transmission: GLSL twin of core/render/transmission_backdrop.h and of
// MissRadiance::transmitted / transmittedRough (core/render/miss_radiance.h). The backdrop is the
// frame's opaque objects (premultiplied radiance, coverage in alpha) with its mip chain
// (core/gl/transmission_pass.*), read texel by texel and interpolated as on the CPU. Needs
// uniforms.glsl and environment.glsl.

#ifdef GLINT_TRANSMISSION_BACKDROP  // a program drawn over a backdrop (gl/transmission_pass.h)
uniform sampler2D transmissionBackdrop;
uniform int transmissionBackdropLevels;  // 0: the frame has no backdrop

// One texel, at its centre with nearest filtering (texelFetch with a level read zeros in quads on
// an object's silhouette on llvmpipe, Mesa 22).
vec4 backdropTexel(ivec2 texel, int level, ivec2 size) {
    return textureLod(transmissionBackdrop, (vec2(texel) + 0.5) / vec2(size), float(level));
}

vec4 backdropBilinear(int level, vec2 uv) {
    ivec2 size = textureSize(transmissionBackdrop, level);
    vec2 position = uv * vec2(size) - 0.5;
    vec2 corner = floor(position), weight = position - corner;
    ivec2 low = clamp(ivec2(corner), ivec2(0), size - 1), high = clamp(ivec2(corner) + 1, ivec2(0), size - 1);
    vec4 bottom = mix(backdropTexel(ivec2(low.x, low.y), level, size),
                      backdropTexel(ivec2(high.x, low.y), level, size), weight.x);
    vec4 top = mix(backdropTexel(ivec2(low.x, high.y), level, size),
                   backdropTexel(ivec2(high.x, high.y), level, size), weight.x);
    return mix(bottom, top, weight.y);
}

vec4 backdropSample(vec2 uv, float level) {
    float clamped = clamp(level, 0.0, float(transmissionBackdropLevels - 1));
    int lower = int(floor(clamped));
    int upper = min(lower + 1, transmissionBackdropLevels - 1);
    if (upper == lower || clamped == float(lower)) return backdropBilinear(lower, uv);
    return mix(backdropBilinear(lower, uv), backdropBilinear(upper, uv), clamped - float(lower));
}

float backdropLevelFor(float perceptualRoughness, float ior) {
    return log2(float(textureSize(transmissionBackdrop, 0).x)) * perceptualRoughness * clamp(2.0 * ior - 2.0, 0.0, 1.0);
}

// Twin of MissRadiance::throughBackdrop (with TransmissionBackdrop::behind): the premultiplied
// radiance of the opaque objects where the ray leaves, over `beyond` where they do not cover it.
vec3 throughBackdrop(vec3 exitPoint, vec3 direction, vec3 viewDirection, float level, vec3 beyond) {
    if (transmissionBackdropLevels == 0 || dot(direction, viewDirection) <= 0.0) return beyond;
    vec4 clip = viewProjection * vec4(exitPoint, 1.0);
    if (clip.w <= 0.0) return beyond;
    vec2 uv = 0.5 * clip.xy / clip.w + 0.5;
    if (uv.x < 0.0 || uv.x > 1.0 || uv.y < 0.0 || uv.y > 1.0) return beyond;
    vec4 seen = backdropSample(uv, level);
    return seen.rgb + (1.0 - seen.a) * beyond;
}

vec3 transmittedRadiance(vec3 exitPoint, vec3 direction, vec3 viewDirection) {
    return throughBackdrop(exitPoint, direction, viewDirection, 0.0, missRadiance(direction));
}

vec3 transmittedRadianceRough(vec3 exitPoint, vec3 direction, vec3 viewDirection, float perceptualRoughness, float ior) {
    float level = transmissionBackdropLevels > 0 ? backdropLevelFor(perceptualRoughness, ior) : 0.0;
    return throughBackdrop(exitPoint, direction, viewDirection, level, missRadianceRough(direction, perceptualRoughness));
}
#else
// No backdrop: a transmitted ray sees what a ray that misses the scene sees.
vec3 throughBackdrop(vec3 exitPoint, vec3 direction, vec3 viewDirection, float level, vec3 beyond) {
    return beyond;
}

vec3 transmittedRadiance(vec3 exitPoint, vec3 direction, vec3 viewDirection) {
    return missRadiance(direction);
}

vec3 transmittedRadianceRough(vec3 exitPoint, vec3 direction, vec3 viewDirection, float perceptualRoughness, float ior) {
    return missRadianceRough(direction, perceptualRoughness);
}
#endif
