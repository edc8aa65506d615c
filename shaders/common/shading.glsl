// The shading sum at one surface point: f_r · E⊥ · cos θ over the lights, with the model's
// generated MaterialParams. GLSL twin of shadeHit() in core/render/reference_renderer.cpp.
// Needs uniforms.glsl, frame.glsl, lights.glsl and generated/material.glsl first.

vec3 shadeSurface(vec3 position, ShadingFrame frame, vec3 towardsViewer) {
    MaterialParams params = loadMaterialParams();
    vec3 radiance = vec3(0.0);
    for (int i = 0; i < lightCount.x; ++i) {
        LightArrival arrival = lightArrival(lights[i], position);
        float cosIn = cosTheta(frame, arrival.towardsLight);
        if (cosIn <= 0.0) continue;
        // L_o = f_r(ω_i, ω_o) · E⊥ · cos θ_i for each delta light.
        radiance += GLINT_EVAL_BRDF(params, arrival.towardsLight, towardsViewer, frame) *
                    arrival.normalIrradiance * cosIn;
    }
    return radiance;
}
