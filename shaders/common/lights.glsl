// What one delta light delivers at a point: the GLSL twin of lightArrival() and spotFactor() in
// core/light/light.h. Ambient lights arrive as FrameBlock.ambientRadiance, not here.

struct LightArrival {
    vec3 towardsLight;      // unit
    vec3 normalIrradiance;  // E⊥ [W/m²]
};

// Hearn-Baker cone falloff cos^a α with a smooth edge from cos θ_c (0) to cos(θ_c − w) (1).
float spotFactor(float cosAlpha, float cosOuter, float cosInner, float falloffExponent) {
    if (cosAlpha <= 0.0 || cosAlpha <= cosOuter) return 0.0;
    float edge = 1.0;
    if (cosAlpha < cosInner) {
        float t = (cosAlpha - cosOuter) / (cosInner - cosOuter);
        edge = t * t * (3.0 - 2.0 * t);
    }
    return pow(cosAlpha, falloffExponent) * edge;
}

LightArrival lightArrival(GpuLight light, vec3 point) {
    vec3 toLight = light.position.xyz - point * light.position.w;
    LightArrival arrival;
    arrival.towardsLight = normalize(toLight);
    if (light.position.w == 0.0) {  // directional: E⊥ = M
        arrival.normalIrradiance = light.emission.rgb;
        return arrival;
    }
    // Point and spot: E⊥ = I/d² (inverse-square law), or the classic 1/(a0 + a1·d + a2·d²).
    float distance = length(toLight);
    float distanceFactor = light.attenuation.w > 0.5
        ? 1.0 / (light.attenuation.x + light.attenuation.y * distance + light.attenuation.z * distance * distance)
        : 1.0 / (distance * distance);
    arrival.normalIrradiance = light.emission.rgb * distanceFactor;
    if (light.spotAxis.w > -1.5) {
        float cosAlpha = dot(-arrival.towardsLight, light.spotAxis.xyz);
        arrival.normalIrradiance *= spotFactor(cosAlpha, light.spotAxis.w, light.spotShape.x, light.spotShape.y);
    }
    return arrival;
}
