// The background radiance along a ray leaving the scene: constant or sky gradient. GLSL twin of
// core/scene/background.h; reads the FrameBlock (uniforms.glsl). No environment maps yet.

// The kind is a compile-time constant in a specialised program (gl/shader_specialisation.h).
#ifdef GLINT_BACKGROUND_KIND
const int kBackgroundKind = GLINT_BACKGROUND_KIND;
#else
#define kBackgroundKind backgroundKind.x
#endif

vec3 backgroundRadiance(vec3 direction) {
    if (kBackgroundKind == 0) return background.rgb;
    float elevation = clamp(direction.y, -1.0, 1.0);
    return elevation >= 0.0 ? mix(skyHorizon.rgb, skyZenith.rgb, elevation)
                            : mix(skyHorizon.rgb, skyGround.rgb, -elevation);
}
