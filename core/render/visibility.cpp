// Frustum and back-face culling decisions (see visibility.h).
#include "render/visibility.h"

#include <algorithm>
#include <cmath>

namespace glint {

CulledFaces culledFaces(MeshClosure closure, bool viewerOutside) {
    if (!viewerOutside) return CulledFaces::None;
    switch (closure) {
        case MeshClosure::ClosedOutward: return CulledFaces::Back;
        case MeshClosure::ClosedInward: return CulledFaces::Front;
        case MeshClosure::Open: break;
    }
    return CulledFaces::None;
}

bool beyondNearPlane(const Camera& camera, const BoundingSphere& bounds) {
    const glm::vec3 forward = glm::normalize(camera.target - camera.position);
    return glm::dot(bounds.center - camera.position, forward) - bounds.radius > camera.nearPlane;
}

bool beyondNearPlane(const ShadowProjection& projection, const BoundingSphere& bounds) {
    if (projection.kind == ShadowMapKind::Orthographic) return true;
    const float halfSide = 0.5f * projection.sideScale;  // tan(fov/2); 1 for a cube face
    const float nearCorner = projection.nearPlane * std::sqrt(1.0f + 2.0f * halfSide * halfSide);
    return glm::length(bounds.center - projection.lightPosition) - bounds.radius > nearCorner;
}

bool outsideFrustum(const glm::mat4& viewProjection, const BoundingSphere& bounds) {
    const glm::mat4 rows = glm::transpose(viewProjection);  // rows[i]: the i-th row of the matrix
    const glm::vec4 centre(bounds.center, 1.0f);
    for (int axis = 0; axis < 3; ++axis)
        for (const float side : {1.0f, -1.0f}) {
            const glm::vec4 plane = rows[3] + side * rows[axis];  // −w ≤ x, y, z ≤ w
            if (glm::dot(plane, centre) < -bounds.radius * glm::length(glm::vec3(plane))) return true;
        }
    return false;
}

double coveredPixels(const Camera& camera, const BoundingSphere& bounds, int width, int height) {
    const double image = static_cast<double>(width) * height;
    double halfHeightWorld = 0.5 * camera.orthoHeight;  // the world size of half the image height
    if (camera.projection == Projection::Perspective) {
        if (!beyondNearPlane(camera, bounds)) return image;
        const glm::vec3 forward = glm::normalize(camera.target - camera.position);
        const double depth = glm::dot(bounds.center - camera.position, forward) - bounds.radius;  // its nearest depth
        halfHeightWorld = depth * std::tan(0.5 * glm::radians(static_cast<double>(camera.verticalFovDegrees)));
    }
    const double radiusPixels = bounds.radius / halfHeightWorld * 0.5 * height;
    return std::min(image, 3.14159265358979 * radiusPixels * radiusPixels);
}

}  // namespace glint
