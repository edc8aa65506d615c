// OrbitController: the editor's camera motion (orbit around a target, pan, zoom, reset) as pure
// maths on a Camera; the editor feeds it mouse deltas. Angles in radians.
#pragma once

#include <algorithm>
#include <cmath>

#include <glm/glm.hpp>

#include "camera/camera.h"

namespace glint {

struct OrbitController {
    float yaw = 0.0f;    // around +y, 0 looks along −z
    float pitch = 0.0f;  // above the horizon, in (−π/2, π/2)
    float distance = 4.0f;
    glm::vec3 target{0.0f};

    // Takes yaw, pitch and distance from an existing camera.
    static OrbitController fromCamera(const Camera& camera) {
        OrbitController orbit;
        const glm::vec3 offset = camera.position - camera.target;
        orbit.distance = std::max(glm::length(offset), 1e-3f);
        orbit.pitch = std::asin(std::clamp(offset.y / orbit.distance, -1.0f, 1.0f));
        orbit.yaw = std::atan2(offset.x, offset.z);
        orbit.target = camera.target;
        return orbit;
    }

    void orbit(float deltaYaw, float deltaPitch) {
        yaw += deltaYaw;
        pitch = std::clamp(pitch + deltaPitch, -1.55f, 1.55f);
    }
    // Moves the target in the view plane by a fraction of the distance.
    void pan(float right, float up) {
        const glm::vec3 forward = -offsetDirection();
        const glm::vec3 rightAxis = glm::normalize(glm::cross(forward, glm::vec3(0, 1, 0)));
        const glm::vec3 upAxis = glm::cross(rightAxis, forward);
        target += (rightAxis * right + upAxis * up) * distance;
    }
    // factor < 1 moves closer.
    void zoom(float factor) { distance = std::clamp(distance * factor, 0.05f, 500.0f); }

    glm::vec3 offsetDirection() const {
        return {std::cos(pitch) * std::sin(yaw), std::sin(pitch), std::cos(pitch) * std::cos(yaw)};
    }
    void applyTo(Camera& camera) const {
        camera.target = target;
        camera.position = target + offsetDirection() * distance;
        camera.up = {0, 1, 0};
    }
};

}  // namespace glint
