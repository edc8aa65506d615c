// Hard shadow rays for the CPU reference (see shadow_rays.h).
#include "render/shadow_rays.h"

#include <algorithm>
#include <cmath>

namespace glint {

float rayOriginOffset(glm::vec3 position) {
    const glm::vec3 magnitude = glm::abs(position);
    return 1e-4f * std::max({1.0f, magnitude.x, magnitude.y, magnitude.z});
}

float lightVisibility(const Scene& scene, const Light& light, const SurfaceHit& hit, const LightArrival& arrival) {
    if (!light.castsShadows || light.type == LightType::Ambient) return 1.0f;
    const Ray shadowRay{hit.position + rayOriginOffset(hit.position) * hit.normal, arrival.towardsLight};
    const auto blocker = intersectScene(scene, shadowRay);
    // A directional light is at infinity: any hit blocks it; a point or spot light only when the
    // blocker lies before the light.
    return blocker && blocker->distance < arrival.distance ? 0.0f : 1.0f;
}

}  // namespace glint
