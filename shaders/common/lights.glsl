// What one delta light delivers at a point: the GLSL twin of lightArrival() and spotFactor() in
// core/light/light.h. Ambient lights arrive as FrameBlock.ambientRadiance, not here.

// What is known of a light when its program is compiled (gl/shader_specialisation.h): nothing
// (read everything from LightBlock), a directional light, or a point light with the inverse-square
// law and no cone. A known kind lets the compiler drop the other kinds' code.
const int LIGHT_ANY = -1;
const int LIGHT_DIRECTIONAL = 0;
const int LIGHT_POINT = 1;

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

LightArrival lightArrival(GpuLight light, vec3 point, int kind) {
    LightArrival arrival;
    if (kind == LIGHT_DIRECTIONAL || (kind == LIGHT_ANY && light.position.w == 0.0)) {  // directional: E⊥ = M
        arrival.towardsLight = normalize(light.position.xyz);
        arrival.normalIrradiance = light.emission.rgb;
        return arrival;
    }
    // Point and spot: E⊥ = I/d² (inverse-square law), or the classic 1/(a0 + a1·d + a2·d²).
    vec3 toLight = light.position.xyz - point;
    arrival.towardsLight = normalize(toLight);
    float distance = length(toLight);
    if (kind == LIGHT_POINT) {
        arrival.normalIrradiance = light.emission.rgb * (1.0 / (distance * distance));
        return arrival;
    }
    vec3 law = light.attenuation.xyz;  // (0, 0, 1): the inverse-square law
    arrival.normalIrradiance = light.emission.rgb * (1.0 / (law.x + law.y * distance + law.z * distance * distance));
    if (light.spotAxis.w > -1.5) {
        float cosAlpha = dot(-arrival.towardsLight, light.spotAxis.xyz);
        arrival.normalIrradiance *= spotFactor(cosAlpha, light.spotAxis.w, light.emission.w, light.attenuation.w);
    }
    return arrival;
}
