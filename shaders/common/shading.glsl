// The shading sum at one surface point: f_r · E⊥ · cos θ over the lights, k_a · L_a for the
// ambient light and the model's traced delta lobes, with the model's generated MaterialParams.
// GLSL twin of shadeHit() in core/render/reference_renderer.cpp.
// Needs uniforms.glsl, frame.glsl, lights.glsl and generated/material.glsl first.
#include "common/shadows.glsl"
#include "common/sphere_occlusion.glsl"

vec3 shadeSurface(vec3 position, ShadingFrame frame, vec3 towardsViewer) {
    MaterialParams params = loadMaterialParams();
    vec3 radiance = vec3(0.0);
    for (int i = 0; i < lightCount.x; ++i) {
        LightArrival arrival = lightArrival(lights[i], position);
        float cosIn = cosTheta(frame, arrival.towardsLight);
        if (cosIn <= 0.0) continue;
        // L_o = f_r(ω_i, ω_o) · E⊥ · cos θ_i · V for each delta light (V: shadows.glsl).
        float visibility = shadowVisibility(i, position, frame.normal, arrival.towardsLight);
        if (visibility == 0.0) continue;
        radiance += GLINT_EVAL_BRDF(params, arrival.towardsLight, towardsViewer, frame) *
                    arrival.normalIrradiance * cosIn * visibility;
    }
    // Ambient: k_a · L_a (GLINT_AMBIENT_REFLECTANCE is the registry's hook, zero when absent).
    radiance += GLINT_AMBIENT_REFLECTANCE(params, towardsViewer, frame) * ambientRadiance.rgb;
#ifdef GLINT_ENVIRONMENT_LIGHTING
    // Environment light: the model's image-based lighting hook (registry glslEnvironment), less
    // what the scene's spheres cover (sphere_occlusion.glsl).
    if (environmentFlags.x != 0)
        radiance += GLINT_ENVIRONMENT_LIGHTING(params, towardsViewer, frame) * environmentVisibility(position, frame.normal);
#endif
#ifdef GLINT_SPECULAR_TRANSPORT
    radiance += GLINT_SPECULAR_TRANSPORT(params, position, frame, towardsViewer);
#endif
    return radiance;
}
