// Frustum and back-face culling decisions (see visibility.h).
#include "render/visibility.h"

#include <algorithm>
#include <cmath>

#include "math/constants.h"

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

PixelRegion intersectionOf(const PixelRegion& a, const PixelRegion& b) {
    const int x = std::max(a.x, b.x), y = std::max(a.y, b.y);
    return {x, y, std::max(0, std::min(a.x + a.width, b.x + b.width) - x), std::max(0, std::min(a.y + a.height, b.y + b.height) - y)};
}

PixelRegion boundsOf(const PixelRegion& a, const PixelRegion& b) {
    if (a.empty()) return b;
    if (b.empty()) return a;
    const int x = std::min(a.x, b.x), y = std::min(a.y, b.y);
    return {x, y, std::max(a.x + a.width, b.x + b.width) - x, std::max(a.y + a.height, b.y + b.height) - y};
}

PixelRegion coveredRect(const Camera& camera, const BoundingSphere& bounds, int width, int height) {
    const glm::mat4 projection = camera.projectionMatrix(static_cast<float>(width) / height);
    const glm::vec3 center = glm::vec3(camera.view() * glm::vec4(bounds.center, 1.0f));  // the eye looks along −z
    const float size[2] = {static_cast<float>(width), static_cast<float>(height)};
    int low[2], high[2];  // per axis (x, y): the pixels spanned
    for (int axis = 0; axis < 2; ++axis) {
        float from, to;  // normalised device coordinates
        if (camera.projection == Projection::Orthographic) {
            from = projection[axis][axis] * (center[axis] - bounds.radius) + projection[3][axis];
            to = projection[axis][axis] * (center[axis] + bounds.radius) + projection[3][axis];
        } else {
            // Projected along this axis, the sphere spans the angle between the two lines through
            // the eye that touch its outline in the plane of the axis and the view direction.
            const float distance = std::hypot(center[axis], center.z);
            if (distance <= bounds.radius) return {0, 0, width, height};
            const float direction = std::atan2(center[axis], -center.z), halfAngle = std::asin(bounds.radius / distance);
            if (std::abs(direction) + halfAngle >= 0.5f * kPi) return {0, 0, width, height};  // reaches behind the eye
            from = projection[axis][axis] * std::tan(direction - halfAngle);
            to = projection[axis][axis] * std::tan(direction + halfAngle);
        }
        // A pixel's samples lie within it: a pixel's margin on each side.
        const auto pixel = [&](float ndc) { return std::clamp((0.5f * ndc + 0.5f) * size[axis], -1.0f, size[axis] + 1.0f); };
        low[axis] = std::clamp(static_cast<int>(std::floor(pixel(from))) - 1, 0, static_cast<int>(size[axis]));
        high[axis] = std::clamp(static_cast<int>(std::ceil(pixel(to))) + 1, 0, static_cast<int>(size[axis]));
    }
    return {low[0], low[1], std::max(0, high[0] - low[0]), std::max(0, high[1] - low[1])};
}

}  // namespace glint
