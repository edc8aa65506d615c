// What a ray that leaves the scene sees: the environment map when the scene has one (secondary
// rays always; primary rays when it is shown as the background), else the background; a
// transmitted ray sees the frame's opaque pass first where it is given (render/transmission_backdrop.h).
// Used by the specular transport and the reference renderer; GLSL twins: missRadiance() and
// primaryMissRadiance() in shaders/common/environment.glsl, transmittedRadiance() in
// shaders/common/transmission_backdrop.glsl.
#pragma once

#include <glm/glm.hpp>

#include "environment/environment_lighting.h"
#include "render/transmission_backdrop.h"
#include "scene/background.h"
#include "scene/environment.h"

namespace glint {

class MissRadiance {
public:
    // Implicit from a Background alone: no environment.
    MissRadiance(const Background& background, const Environment* environment = nullptr,
                 const TransmissionBackdrop* backdrop = nullptr)
        : background_(background), environment_(environment && environment->enabled() ? environment : nullptr),
          backdrop_(backdrop) {}

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
    // A ray transmitted through a smooth surface, leaving its object at `exitPoint` along
    // `direction` (the viewer looking along `viewDirection`): the opaque objects the backdrop's
    // base level shows at that point, and as operator() where they do not cover it.
    glm::vec3 transmitted(glm::vec3 exitPoint, glm::vec3 direction, glm::vec3 viewDirection) const {
        return throughBackdrop(exitPoint, direction, viewDirection, 0.0f, (*this)(direction));
    }
    // The same through a rough interface of perceptual roughness r and index η: the backdrop at
    // its level for r and η, over rough().
    glm::vec3 transmittedRough(glm::vec3 exitPoint, glm::vec3 direction, glm::vec3 viewDirection, float perceptualRoughness,
                               float ior) const {
        const float level = backdrop_ ? backdrop_->levelFor(perceptualRoughness, ior) : 0.0f;
        return throughBackdrop(exitPoint, direction, viewDirection, level, rough(direction, perceptualRoughness));
    }
    // A primary ray: the environment only where it is shown as the background.
    glm::vec3 primary(glm::vec3 direction) const {
        return environment_ && environment_->showAsBackground ? environmentRadiance(*environment_, direction)
                                                              : backgroundRadiance(background_, direction);
    }

private:
    // The backdrop's premultiplied radiance over `beyond` (what the ray sees where nothing covers it).
    glm::vec3 throughBackdrop(glm::vec3 exitPoint, glm::vec3 direction, glm::vec3 viewDirection, float level,
                              glm::vec3 beyond) const {
        if (!backdrop_) return beyond;
        const auto seen = backdrop_->behind(exitPoint, direction, viewDirection, level);
        return seen ? glm::vec3(*seen) + (1.0f - seen->a) * beyond : beyond;
    }

    Background background_;
    const Environment* environment_;
    const TransmissionBackdrop* backdrop_;
};

}  // namespace glint
