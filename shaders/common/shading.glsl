// The shading sum at one surface point: f_r · E⊥ · cos θ over the lights, k_a · L_a for the
// ambient light and the model's traced delta lobes, with the model's generated MaterialParams.
// GLSL twin of shadeHit() in core/render/reference_renderer.cpp.
// Needs uniforms.glsl, frame.glsl, lights.glsl and generated/material.glsl first.
#include "common/shadows.glsl"
#include "common/sphere_occlusion.glsl"

// One delta light's L_o = f_r(ω_i, ω_o) · E⊥ · cos θ_i · V (V: shadows.glsl). `kind`, the shadow
// map's `shadowSlot` (−1: none) and `shadowKind` are constants in a specialised program
// (gl/shader_specialisation.h), so the compiler keeps only the code this light needs.
vec3 lightTerm(MaterialParams params, int i, int kind, int shadowSlot, int shadowKind, vec3 position, ShadingFrame frame,
               vec3 towardsViewer) {
    LightArrival arrival = lightArrival(lights[i], position, kind);
    float cosIn = cosTheta(frame, arrival.towardsLight);
    if (cosIn <= 0.0) return vec3(0.0);
    float visibility = shadowVisibility(shadowSlot, shadowKind, position, frame.normal, arrival.towardsLight);
    if (visibility == 0.0) return vec3(0.0);
    return GLINT_EVAL_BRDF(params, arrival.towardsLight, towardsViewer, frame) * arrival.normalIrradiance * cosIn *
           visibility;
}

// The sum over LightBlock lights [first, end), all of one kind. `first`, `end` and `kind` are
// constants in a specialised program, so the body is compiled for that kind alone; a do-while loop
// costs llvmpipe exactly its passes (docs/performance.md), and the program does not grow with them.
vec3 loopedLightSum(MaterialParams params, int first, int end, int kind, vec3 position, ShadingFrame frame,
                    vec3 towardsViewer) {
    vec3 sum = vec3(0.0);
    int i = first;
    do {
        sum += lightTerm(params, i, kind, -1, 0, position, frame, towardsViewer);
    } while (++i < end);
    return sum;
}

vec3 shadeSurface(vec3 position, ShadingFrame frame, vec3 towardsViewer) {
    MaterialParams params = loadMaterialParams();
    vec3 radiance = vec3(0.0);
#ifdef GLINT_LIGHT_SUM
    // Specialised: the first and the shadowed lights unrolled, GLINT_LIGHT_SUM(term) = term(i, kind,
    // slot, map kind) + ..., then the others in loops, GLINT_LOOPED_LIGHT_SUM(run) = run(first, end, kind) + ...
#define GLINT_LIGHT_TERM(i, kind, slot, mapKind) lightTerm(params, i, kind, slot, mapKind, position, frame, towardsViewer)
    radiance += GLINT_LIGHT_SUM(GLINT_LIGHT_TERM);
#ifdef GLINT_LOOPED_LIGHT_SUM
#define GLINT_LOOPED_RUN(first, end, kind) loopedLightSum(params, first, end, kind, position, frame, towardsViewer)
    radiance += GLINT_LOOPED_LIGHT_SUM(GLINT_LOOPED_RUN);
#endif
#else
    for (int i = 0; i < lightCount.x; ++i) {
        int slot = shadowSlotOfLight(i);  // −1: no map, and the kind read for slot 0 is unused
        radiance += lightTerm(params, i, LIGHT_ANY, slot, shadowKindOfSlot(max(slot, 0)), position, frame, towardsViewer);
    }
#endif
    // The occlusion map (glTF's occlusionTexture) scales the ambient and environment light only.
#ifdef GLINT_OCCLUSION_SLOT
    float occlusion = textureScalar(GLINT_OCCLUSION_SLOT);
#else
    float occlusion = 1.0;
#endif
    // Ambient: k_a · L_a (GLINT_AMBIENT_REFLECTANCE is the registry's hook, zero when absent).
    radiance += occlusion * GLINT_AMBIENT_REFLECTANCE(params, towardsViewer, frame) * ambientRadiance.rgb;
#ifdef GLINT_ENVIRONMENT_LIGHTING
    // Environment light: the model's image-based lighting hook (registry glslEnvironment), less
    // what the scene's spheres cover (sphere_occlusion.glsl).
    if (environmentEnabled())
        radiance += occlusion * GLINT_ENVIRONMENT_LIGHTING(params, towardsViewer, frame) * environmentVisibility(position, frame.normal);
#endif
#ifdef GLINT_SPECULAR_TRANSPORT
    radiance += GLINT_SPECULAR_TRANSPORT(params, position, frame, towardsViewer);
#endif
    return radiance;
}
