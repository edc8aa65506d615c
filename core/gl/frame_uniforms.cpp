// Scene → FrameBlock and LightBlock packing (see frame_uniforms.h).
#include "gl/frame_uniforms.h"

#include "light/light.h"

namespace glint {

FrameUniforms packFrameUniforms(const Scene& scene, int width, int height) {
    FrameUniforms packed;
    FrameBlockStd140& frame = packed.frame;
    frame.viewProjection = scene.camera.viewProjection(static_cast<float>(width) / height);
    frame.inverseViewProjection = glm::inverse(frame.viewProjection);
    frame.viewportSize = {width, height, 0, 0};
    frame.background = glm::vec4(scene.background.color, 1.0f);
    frame.skyZenith = glm::vec4(scene.background.zenith, 1.0f);
    frame.skyHorizon = glm::vec4(scene.background.horizon, 1.0f);
    frame.skyGround = glm::vec4(scene.background.ground, 1.0f);
    frame.backgroundKind = {scene.background.kind == BackgroundKind::Sky ? 1 : 0, 0, 0, 0};
    int count = 0;
    glm::vec3 ambient(0.0f);
    for (const Light& light : scene.lights) {
        if (!light.enabled) continue;
        if (light.type == LightType::Ambient) {
            ambient += ambientRadiance(light);
            continue;
        }
        if (count == kMaxLights) continue;
        GpuLightStd140& gpu = packed.lights.lights[count++];
        gpu.spotAxis = glm::vec4(0.0f, 0.0f, 0.0f, -2.0f);  // no cone
        gpu.attenuation = glm::vec4(light.attenuation.enabled ? light.attenuation.coefficients : kInverseSquareLaw, 0.0f);
        if (light.type == LightType::Directional) {
            gpu.position = glm::vec4(-glm::normalize(light.direction), 0.0f);
            gpu.emission = glm::vec4(light.color * light.irradiance, 0.0f);
            continue;
        }
        gpu.position = glm::vec4(light.position, 1.0f);
        gpu.emission = glm::vec4(pointIntensity(light), 0.0f);  // I = Φ/4π
        if (light.type == LightType::Spot) {
            gpu.spotAxis = glm::vec4(glm::normalize(light.direction), spotCosOuter(light));
            gpu.emission.w = spotCosInner(light);
            gpu.attenuation.w = light.falloffExponent;
        }
    }
    frame.ambientRadiance = glm::vec4(ambient, 0.0f);
    frame.lightCount = {count, 0, 0, 0};
    return packed;
}

}  // namespace glint
