// Camera matrices and primary rays (see camera.h).
#include "camera/camera.h"

#include <glm/gtc/matrix_transform.hpp>

namespace glint {

glm::mat4 Camera::view() const { return glm::lookAt(position, target, up); }

glm::mat4 Camera::projectionMatrix(float aspect) const {
    if (projection == Projection::Orthographic) {
        const float halfHeight = 0.5f * orthoHeight;
        const float halfWidth = halfHeight * aspect;
        return glm::ortho(-halfWidth, halfWidth, -halfHeight, halfHeight, nearPlane, farPlane);
    }
    return glm::perspective(glm::radians(verticalFovDegrees), aspect, nearPlane, farPlane);
}

Ray primaryRay(const glm::mat4& inverseViewProjection, float x, float y, int width, int height) {
    // Pixel to normalised device coordinates; image rows run top to bottom, NDC y runs up.
    const float ndcX = 2.0f * x / width - 1.0f;
    const float ndcY = 1.0f - 2.0f * y / height;
    glm::vec4 nearPoint = inverseViewProjection * glm::vec4(ndcX, ndcY, -1.0f, 1.0f);
    glm::vec4 farPoint = inverseViewProjection * glm::vec4(ndcX, ndcY, 1.0f, 1.0f);
    const glm::vec3 origin = glm::vec3(nearPoint) / nearPoint.w;
    const glm::vec3 end = glm::vec3(farPoint) / farPoint.w;
    return {origin, glm::normalize(end - origin)};
}

glm::vec3 towardsViewerFrom(const Camera& camera, glm::vec3 position) {
    if (camera.projection == Projection::Perspective) return glm::normalize(camera.position - position);
    return glm::normalize(camera.position - camera.target);
}

float viewerDistance(const Camera& camera, glm::vec3 position) {
    const glm::vec3 forward = glm::normalize(camera.target - camera.position);
    const glm::vec3 offset = position - camera.position;
    if (camera.projection == Projection::Orthographic) return glm::dot(offset, forward) - camera.nearPlane;
    // Along the line from the eye: the near plane lies at depth `near`, i.e. near / cos of the way.
    const float length = glm::length(offset);
    return length - camera.nearPlane * length / glm::dot(offset, forward);
}

}  // namespace glint
