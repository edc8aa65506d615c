// Shadow-map projections (see shadow_projection.h).
#include "render/shadow_projection.h"

#include <algorithm>
#include <cmath>

#include <glm/gtc/matrix_transform.hpp>

#include "math/frame.h"

namespace glint {
namespace {

// An up vector for a look-at along `forward` that is not parallel to it.
glm::vec3 upFor(glm::vec3 forward) {
    return std::abs(forward.y) > 0.99f ? glm::vec3(0.0f, 0.0f, 1.0f) : glm::vec3(0.0f, 1.0f, 0.0f);
}

}  // namespace

BoundingSphere sceneBounds(const Scene& scene) {
    static_assert(std::variant_size_v<Shape> == 5, "give the new shape's extent to sceneBounds");
    glm::vec3 low(INFINITY), high(-INFINITY);
    const auto include = [&](glm::vec3 centre, glm::vec3 halfExtent) {
        low = glm::min(low, centre - halfExtent);
        high = glm::max(high, centre + halfExtent);
    };
    for (const SceneObject& object : scene.objects) {
        if (const auto* sphere = std::get_if<SphereShape>(&object.shape)) {
            include(sphere->center, glm::vec3(sphere->radius));
        } else if (const auto* plane = std::get_if<PlaneShape>(&object.shape)) {
            const ShadingFrame frame = ShadingFrame::fromNormal(glm::normalize(plane->normal));
            for (float u : {-0.5f, 0.5f})
                for (float v : {-0.5f, 0.5f})
                    include(plane->center + u * plane->size.x * frame.tangent + v * plane->size.y * frame.bitangent, glm::vec3(0.0f));
        } else if (const auto* cube = std::get_if<CubeShape>(&object.shape)) {
            include(cube->center, glm::vec3(0.5f * cube->size));
        } else if (const auto* torus = std::get_if<TorusShape>(&object.shape)) {  // around +y
            const float outer = torus->majorRadius + torus->minorRadius;
            include(torus->center, glm::vec3(outer, torus->minorRadius, outer));
        } else {
            const auto& mesh = std::get<MeshShape>(object.shape);  // inside the sphere of radius `scale`
            include(mesh.center, glm::vec3(mesh.scale));
        }
    }
    if (scene.objects.empty()) return {};
    // A little room so that the outermost surfaces do not sit on the map's clip planes.
    return {0.5f * (low + high), 0.5f * glm::length(high - low) * 1.01f + 1e-3f};
}

std::optional<ShadowProjection> shadowProjection(const Light& light, const BoundingSphere& bounds) {
    ShadowProjection projection;
    const float radius = std::max(bounds.radius, 1e-3f);
    switch (light.type) {
        case LightType::Ambient: return std::nullopt;
        case LightType::Directional: {
            // An orthographic box around the bounding sphere, looking along the light's travel.
            const glm::vec3 travel = glm::normalize(light.direction);
            const glm::vec3 eye = bounds.center - 2.0f * radius * travel;
            projection.kind = ShadowMapKind::Orthographic;
            projection.nearPlane = radius;
            projection.farPlane = 3.0f * radius;
            projection.viewProjection = glm::ortho(-radius, radius, -radius, radius, projection.nearPlane, projection.farPlane) *
                                        glm::lookAt(eye, bounds.center, upFor(travel));
            projection.sideScale = 2.0f * radius;
            return projection;
        }
        case LightType::Point:
        case LightType::Spot: break;
    }
    projection.lightPosition = light.position;
    projection.farPlane = glm::length(light.position - bounds.center) + radius;
    projection.nearPlane = 1e-3f * projection.farPlane;
    if (light.type == LightType::Spot && light.coneHalfAngleDegrees <= kWidestPerspectiveSpotDegrees) {
        const glm::vec3 axis = glm::normalize(light.direction);
        const float fovRadians = 2.0f * glm::radians(light.coneHalfAngleDegrees);
        projection.kind = ShadowMapKind::Perspective;
        projection.viewProjection = glm::perspective(fovRadians, 1.0f, projection.nearPlane, projection.farPlane) *
                                    glm::lookAt(light.position, light.position + axis, upFor(axis));
        projection.sideScale = 2.0f * std::tan(0.5f * fovRadians);
        return projection;
    }
    projection.kind = ShadowMapKind::Cube;
    projection.sideScale = 2.0f;
    return projection;
}

glm::mat4 cubeFaceViewProjection(const ShadowProjection& projection, int face) {
    // The cube-map face orientations of the GL specification (§8.13, table 8.19): each face looks
    // down its major axis with the listed up vector, so that texture(cube, direction) finds the
    // texel that this view rendered.
    static const glm::vec3 forwards[6] = {{1, 0, 0}, {-1, 0, 0}, {0, 1, 0}, {0, -1, 0}, {0, 0, 1}, {0, 0, -1}};
    static const glm::vec3 ups[6] = {{0, -1, 0}, {0, -1, 0}, {0, 0, 1}, {0, 0, -1}, {0, -1, 0}, {0, -1, 0}};
    const glm::vec3& eye = projection.lightPosition;
    return glm::perspective(glm::radians(90.0f), 1.0f, projection.nearPlane, projection.farPlane) *
           glm::lookAt(eye, eye + forwards[face], ups[face]);
}

}  // namespace glint
