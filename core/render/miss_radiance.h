// What a ray that leaves the scene sees: the environment map when the scene has one (secondary
// rays always; primary rays when it is shown as the background), else the background. Used by
// the specular transport and the reference renderer; GLSL twin: missRadiance() and
// primaryMissRadiance() in shaders/common/environment.glsl.
#pragma once

#include <glm/glm.hpp>

#include "environment/environment_lighting.h"
#include "scene/background.h"
#include "scene/environment.h"

namespace glint {

class MissRadiance {
public:
    // Implicit from a Background alone: no environment.
    MissRadiance(const Background& background, const Environment* environment = nullptr)
        : background_(background), environment_(environment && environment->enabled() ? environment : nullptr) {}

    // A secondary ray (reflected or refracted): the environment if there is one.
    glm::vec3 operator()(glm::vec3 direction) const {
        return environment_ ? environmentRadiance(*environment_, direction) : backgroundRadiance(background_, direction);
    }
    // A secondary ray leaving a rough interface: the environment prefiltered for perceptual
    // roughness r (its GGX lobe around `direction`), else the background unblurred.
    glm::vec3 rough(glm::vec3 direction, float perceptualRoughness) const {
        return environment_ ? environmentSpecularRadiance(*environment_, direction, perceptualRoughness)
                            : backgroundRadiance(background_, direction);
    }
    // A primary ray: the environment only where it is shown as the background.
    glm::vec3 primary(glm::vec3 direction) const {
        return environment_ && environment_->showAsBackground ? environmentRadiance(*environment_, direction)
                                                              : backgroundRadiance(background_, direction);
    }

private:
    Background background_;
    const Environment* environment_;
};

}  // namespace glint
