// Shadow-map visibility of a delta light at a surface point: the GLSL twin of lightVisibility()
// in core/render/shadow_rays.h, filtered over a fixed Poisson disk (percentage-closer filtering,
// Reeves et al. 1987) with hardware depth comparison on each tap, four taps first. The maps are made by
// core/gl/shadow_maps.cpp; the ShadowBlock mirror is ShadowBlockStd140 in core/gl/shadow_maps.h.
// Needs uniforms.glsl first.

const int MAX_SHADOW_MAPS = 4;
const int SHADOW_ORTHOGRAPHIC = 0;
const int SHADOW_PERSPECTIVE = 1;
const int SHADOW_CUBE = 2;

layout(std140) uniform ShadowBlock {
    mat4 shadowViewProjection[MAX_SHADOW_MAPS];  // world → clip of a 2D map
    vec4 shadowOrigin[MAX_SHADOW_MAPS];          // xyz: light position (perspective, cube); w: kind
    vec4 shadowSettings[MAX_SHADOW_MAPS];        // x: depth bias, y: normal offset, z: filter radius [texels]; w: resolution
    vec4 shadowScale[MAX_SHADOW_MAPS];           // x: map side per unit clip w [m]; y: far plane [m] (cube)
    ivec4 shadowMapOfLight[MAX_LIGHTS / 4];      // per LightBlock index: map slot, or −1 for no shadow
};

uniform sampler2DShadow shadowMaps[MAX_SHADOW_MAPS];
uniform samplerCubeShadow shadowCubes[MAX_SHADOW_MAPS];

// 16 taps of a Poisson disk in the unit circle (fixed, so that pictures are repeatable). The
// first four lie in four different quadrants near the rim: where all four agree the point is
// taken as fully lit or fully shadowed and the other twelve are skipped (most of the picture).
const vec2 kPoissonDisk[16] = vec2[](
    vec2(-0.94201624, -0.39906216), vec2(0.97484398, 0.75648379), vec2(0.44323325, -0.97511554),
    vec2(-0.24188840, 0.99706507), vec2(0.94558609, -0.76890725), vec2(-0.09418410, -0.92938870),
    vec2(0.34495938, 0.29387760), vec2(-0.91588581, 0.45771432), vec2(-0.81544232, -0.87912464),
    vec2(-0.38277543, 0.27676845), vec2(0.53742981, -0.47373420), vec2(-0.26496911, -0.41893023),
    vec2(0.79197514, 0.19090188), vec2(-0.81409955, 0.91437590), vec2(0.19984126, 0.78641367),
    vec2(0.14383161, -0.14100790));
const int kEarlyTaps = 4;

// Sampler arrays are indexed by constants only (GLSL 4.10 allows dynamically uniform indices, but
// not every driver handles them well). llvmpipe runs every arm of a choice, so a slot that is not a
// compile-time constant costs four lookups a tap: a specialised program passes constants.
float compare2D(int slot, vec3 uvDepth) {
    if (slot == 0) return texture(shadowMaps[0], uvDepth);
    if (slot == 1) return texture(shadowMaps[1], uvDepth);
    if (slot == 2) return texture(shadowMaps[2], uvDepth);
    return texture(shadowMaps[3], uvDepth);
}

float compareCube(int slot, vec4 directionDistance) {
    if (slot == 0) return texture(shadowCubes[0], directionDistance);
    if (slot == 1) return texture(shadowCubes[1], directionDistance);
    if (slot == 2) return texture(shadowCubes[2], directionDistance);
    return texture(shadowCubes[3], directionDistance);
}

// The shadow-map slot of light `lightIndex` (−1: none) and its map's kind, from the block.
int shadowSlotOfLight(int lightIndex) { return shadowMapOfLight[lightIndex / 4][lightIndex % 4]; }
int shadowKindOfSlot(int slot) { return int(shadowOrigin[slot].w); }

// Fraction of the PCF kernel that sees the light from `position` (1 lit, 0 in shadow), through map
// `slot` of kind `kind` (both compile-time constants in a specialised program). `normal` faces the
// viewer; `towardsLight` is unit.
float shadowVisibility(int slot, int kind, vec3 position, vec3 normal, vec3 towardsLight) {
    if (slot < 0) return 1.0;
    vec4 settings = shadowSettings[slot];
    int taps = settings.z > 0.0 ? 16 : 1;
    float visible = 0.0;
    if (kind == SHADOW_CUBE) {
        // World size of one texel at the point: the cube face spans 2·(major-axis distance).
        vec3 fromLight = position - shadowOrigin[slot].xyz;
        vec3 magnitude = abs(fromLight);
        float texel = shadowScale[slot].x * max(magnitude.x, max(magnitude.y, magnitude.z)) / settings.w;
        vec3 biased = position + texel * (settings.y * normal + settings.x * towardsLight);
        vec3 direction = biased - shadowOrigin[slot].xyz;
        float reference = length(direction) / shadowScale[slot].y;  // stored: distance / far
        vec3 axisU = normalize(cross(direction, abs(direction.y) < 0.99 * length(direction) ? vec3(0, 1, 0) : vec3(1, 0, 0)));
        vec3 axisV = normalize(cross(direction, axisU));
        for (int i = 0; i < taps; ++i) {
            vec2 offset = taps > 1 ? kPoissonDisk[i] * settings.z * texel : vec2(0.0);
            visible += compareCube(slot, vec4(direction + offset.x * axisU + offset.y * axisV, reference));
            if (i == kEarlyTaps - 1 && (visible == 0.0 || visible == float(kEarlyTaps))) return visible / float(kEarlyTaps);
        }
        return visible / float(taps);
    }
    vec4 clip = shadowViewProjection[slot] * vec4(position, 1.0);
    float texel = shadowScale[slot].x * clip.w / settings.w;
    vec3 biased = position + texel * (settings.y * normal + settings.x * towardsLight);
    clip = shadowViewProjection[slot] * vec4(biased, 1.0);
    vec3 mapPoint = 0.5 * clip.xyz / clip.w + 0.5;  // uv and depth in [0, 1]
    // Outside the map: the orthographic map covers every object, a spot's map its whole cone.
    if (clip.w <= 0.0 || any(lessThan(mapPoint, vec3(0.0))) || any(greaterThan(mapPoint, vec3(1.0)))) return 1.0;
    for (int i = 0; i < taps; ++i) {
        vec2 offset = taps > 1 ? kPoissonDisk[i] * settings.z / settings.w : vec2(0.0);
        visible += compare2D(slot, vec3(mapPoint.xy + offset, mapPoint.z));
        if (i == kEarlyTaps - 1 && (visible == 0.0 || visible == float(kEarlyTaps))) return visible / float(kEarlyTaps);
    }
    return visible / float(taps);
}
