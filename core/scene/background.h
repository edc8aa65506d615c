// The background: the radiance [W/(sr·m²)] seen along a ray that leaves the scene, either one
// constant colour or a procedural sky gradient (zenith, horizon, ground) over the world's +y.
// CPU half; the GLSL twin is shaders/common/background.glsl. No environment maps (later issue).
#pragma once

#include <glm/glm.hpp>

namespace glint {

enum class BackgroundKind { Constant, Sky };

struct Background {
    BackgroundKind kind = BackgroundKind::Constant;
    glm::vec3 color{0.0f};                 // constant radiance
    glm::vec3 zenith{0.25f, 0.45f, 0.9f};  // sky: radiance straight up (+y)
    glm::vec3 horizon{0.9f, 0.9f, 0.95f};  // sky: radiance at the horizon
    glm::vec3 ground{0.2f, 0.17f, 0.14f};  // sky: radiance straight down
};

// Radiance arriving from the direction `direction` (unit, pointing away from the scene). Sky:
// linear in the elevation's sine y = direction.y, horizon → zenith for y ≥ 0, horizon → ground
// for y < 0; continuous at the horizon.
inline glm::vec3 backgroundRadiance(const Background& background, glm::vec3 direction) {
    if (background.kind == BackgroundKind::Constant) return background.color;
    const float elevation = glm::clamp(direction.y, -1.0f, 1.0f);
    return elevation >= 0.0f ? glm::mix(background.horizon, background.zenith, elevation)
                             : glm::mix(background.horizon, background.ground, -elevation);
}

}  // namespace glint
