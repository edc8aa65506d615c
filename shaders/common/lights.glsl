// What one light delivers at a point: the GLSL twin of lightArrival() in core/light/light.h.

struct LightArrival {
    vec3 towardsLight;      // unit
    vec3 normalIrradiance;  // E⊥ [W/m²]
};

LightArrival lightArrival(GpuLight light, vec3 point) {
    vec3 toLight = light.position.xyz - point * light.position.w;
    // Point: inverse-square law E⊥ = I/d²; directional: E⊥ = M (d² taken as 1).
    float distanceSquared = mix(1.0, dot(toLight, toLight), light.position.w);
    LightArrival arrival;
    arrival.towardsLight = normalize(toLight);
    arrival.normalIrradiance = light.emission.rgb / distanceSquared;
    return arrival;
}
