// Per-light shadow settings: whether a delta light casts shadows and how its shadow map is made
// and filtered (resolution, biases, PCF radius). Plain data with the accepted ranges; the maps
// themselves are core/gl/shadow_maps.h, the CPU twin (hard shadow rays) render/shadow_rays.h.
#pragma once

namespace glint {

// At most this many lights cast shadows at once (each needs a shadow map and a texture unit);
// scene files and the editor refuse more.
inline constexpr int kMaxShadowedLights = 4;
inline constexpr int kMinShadowMapResolution = 16;
inline constexpr int kMaxShadowMapResolution = 4096;
inline constexpr float kMaxShadowBiasTexels = 64.0f;
inline constexpr float kMaxShadowFilterRadiusTexels = 16.0f;

// Biases and the filter radius are in shadow-map texels at the receiver (the world size of one
// texel where the point is), so they stay right when the resolution or the scene's size changes.
struct ShadowSettings {
    int mapResolution = 1024;   // texels per side of the 2D map, or of each cube face
    float depthBias = 1.0f;     // receiver moved towards the light by this many texels (acne)
    float normalOffset = 3.0f;  // ...and along its normal (acne on slopes, Holbein "normal offset shadows", 2011)
    float filterRadius = 1.5f;  // PCF kernel radius; 0 = one bilinear hardware-compared tap
};

}  // namespace glint
