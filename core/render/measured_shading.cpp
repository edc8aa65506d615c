// Measured materials on the CPU reference (see measured_shading.h).
#include "render/measured_shading.h"

#include "environment/environment_lighting.h"

namespace glint {

glm::vec3 measuredAmbientReflectance(const MeasuredBrdf& brdf, glm::vec3 wo, const ShadingFrame& frame) {
    return measuredDirectionalAlbedo(brdf, frame.cosTheta(wo));
}

glm::vec3 measuredEnvironmentLighting(const MeasuredBrdf& brdf, glm::vec3 wo, const ShadingFrame& frame,
                                      const Environment& environment) {
    if (!environment.enabled()) return glm::vec3(0.0f);
    return measuredDirectionalAlbedo(brdf, frame.cosTheta(wo)) * environmentDiffuseRadiance(environment, frame.normal);
}

}  // namespace glint
