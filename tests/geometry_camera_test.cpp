// Procedural meshes, cameras, primary rays, shading frames and the orbit controller.
#include <gtest/gtest.h>

#include "camera/camera.h"
#include "camera/orbit.h"
#include "geometry/mesh.h"
#include "math/frame.h"

namespace glint {
namespace {

TEST(Mesh, UvSphereVerticesLieOnTheSphere) {
    const Mesh mesh = makeUvSphere({1, 2, 3}, 2.0f, 16, 8);
    EXPECT_EQ(mesh.vertices.size(), 17u * 9u);
    EXPECT_EQ(mesh.triangleCount(), 2u * 16u * 8u - 2u * 16u);  // pole rows are fans
    for (const Vertex& vertex : mesh.vertices) {
        EXPECT_NEAR(glm::length(vertex.position - glm::vec3(1, 2, 3)), 2.0f, 1e-5f);
        EXPECT_NEAR(glm::length(vertex.normal), 1.0f, 1e-5f);
        EXPECT_NEAR(glm::dot(vertex.normal, vertex.tangent), 0.0f, 1e-5f);
    }
    for (uint32_t index : mesh.indices) EXPECT_LT(index, mesh.vertices.size());
}

TEST(Mesh, TessellationIsAdjustable) {
    EXPECT_LT(makeUvSphere({}, 1, 8, 4).triangleCount(), makeUvSphere({}, 1, 64, 32).triangleCount());
}

TEST(Mesh, PlaneFacesItsNormal) {
    const Mesh plane = makePlane({0, -1, 0}, {0, 1, 0}, {4, 2});
    EXPECT_EQ(plane.triangleCount(), 2u);
    for (const Vertex& vertex : plane.vertices) {
        EXPECT_FLOAT_EQ(vertex.position.y, -1.0f);
        EXPECT_EQ(vertex.normal, glm::vec3(0, 1, 0));
    }
}

TEST(Frame, IsOrthonormalForAnyNormal) {
    for (glm::vec3 n : {glm::vec3(0, 0, 1), glm::vec3(0, 0, -1), glm::normalize(glm::vec3(1, 2, 3)),
                        glm::normalize(glm::vec3(-1, 0.001f, -0.2f))}) {
        const ShadingFrame frame = ShadingFrame::fromNormal(n);
        EXPECT_NEAR(glm::dot(frame.tangent, frame.bitangent), 0.0f, 1e-6f);
        EXPECT_NEAR(glm::dot(frame.tangent, n), 0.0f, 1e-6f);
        EXPECT_NEAR(glm::length(frame.tangent), 1.0f, 1e-6f);
        const glm::vec3 w = glm::normalize(glm::vec3(0.3f, -0.4f, 0.5f));
        const glm::vec3 back = frame.toWorld(frame.toLocal(w));
        EXPECT_NEAR(glm::length(back - w), 0.0f, 1e-6f);
        EXPECT_NEAR(frame.toLocal(n).z, 1.0f, 1e-6f);
    }
}

TEST(Camera, OrthographicRaysAreParallelAndSpanTheView) {
    Camera camera;
    camera.projection = Projection::Orthographic;
    camera.position = {0, 0, 5};
    camera.orthoHeight = 2.2f;
    const glm::mat4 inverse = glm::inverse(camera.viewProjection(1.0f));
    const Ray centre = primaryRay(inverse, 128, 128, 256, 256);
    EXPECT_NEAR(centre.origin.x, 0.0f, 1e-5f);
    EXPECT_NEAR(centre.direction.z, -1.0f, 1e-6f);
    const Ray corner = primaryRay(inverse, 0, 0, 256, 256);  // top-left corner of the image
    EXPECT_NEAR(corner.origin.x, -1.1f, 1e-5f);
    EXPECT_NEAR(corner.origin.y, 1.1f, 1e-5f);
    EXPECT_NEAR(corner.direction.z, -1.0f, 1e-6f);
}

TEST(Camera, PerspectiveRaysStartAtTheEyeAndSpanTheFieldOfView) {
    Camera camera;
    camera.position = {0, 0, 4};
    camera.verticalFovDegrees = 90.0f;
    const glm::mat4 inverse = glm::inverse(camera.viewProjection(2.0f));
    const Ray top = primaryRay(inverse, 100, 0, 200, 100);
    const glm::vec3 fromEye = top.origin - camera.position;
    EXPECT_NEAR(glm::length(glm::cross(fromEye, top.direction)), 0.0f, 1e-4f);
    EXPECT_NEAR(top.direction.y, -top.direction.z, 1e-4f);  // 45° above the axis
}

TEST(Orbit, KeepsDistanceAndTarget) {
    Camera camera;
    camera.position = {0, 0, 4};
    OrbitController orbit = OrbitController::fromCamera(camera);
    orbit.orbit(0.7f, 0.3f);
    orbit.applyTo(camera);
    EXPECT_NEAR(glm::length(camera.position - camera.target), 4.0f, 1e-5f);
    orbit.zoom(0.5f);
    orbit.applyTo(camera);
    EXPECT_NEAR(glm::length(camera.position - camera.target), 2.0f, 1e-5f);
    orbit.orbit(0.0f, 10.0f);  // pitch is clamped short of the pole
    EXPECT_LT(orbit.pitch, 1.5708f);
}

}  // namespace
}  // namespace glint
