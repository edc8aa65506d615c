// Closed-mesh detection (geometry/mesh_topology.h) on the procedural shapes, open and broken
// meshes, inside-out and two-sided ones, welding by position; and the culling decisions built on it
// (render/visibility.h): which faces a camera or a shadow map may skip, frustum rejection, and the
// pixels a sphere may cover (how many, and the rectangle that holds them).
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>

#include "geometry/mesh_topology.h"
#include "render/visibility.h"

namespace glint {
namespace {

Mesh reversed(Mesh mesh) {
    for (size_t i = 0; i < mesh.indices.size(); i += 3) std::swap(mesh.indices[i + 1], mesh.indices[i + 2]);
    return mesh;
}

Mesh merged(const Mesh& a, const Mesh& b) {
    Mesh mesh = a;
    const auto offset = static_cast<uint32_t>(a.vertices.size());
    mesh.vertices.insert(mesh.vertices.end(), b.vertices.begin(), b.vertices.end());
    for (uint32_t index : b.indices) mesh.indices.push_back(index + offset);
    return mesh;
}

TEST(MeshTopology, ProceduralSolidsAreClosedAndTurnOutwards) {
    // The cube's faces have their own corners and the sphere and torus a UV seam: welding joins
    // them.
    EXPECT_EQ(meshClosure(makeCube({0, 0, 0}, 1.0f)), MeshClosure::ClosedOutward);
    EXPECT_EQ(meshClosure(makeUvSphere({1, 2, 3}, 0.5f, 32, 16)), MeshClosure::ClosedOutward);
    EXPECT_EQ(meshClosure(makeUvSphere({0, 0, 0}, 1.0f, 3, 2)), MeshClosure::ClosedOutward);
    EXPECT_EQ(meshClosure(makeTorus({0, 0, 0}, 1.0f, 0.3f, 24, 12)), MeshClosure::ClosedOutward);
}

TEST(MeshTopology, OpenAndBrokenMeshesAreOpen) {
    EXPECT_EQ(meshClosure(makePlane({0, 0, 0}, {0, 1, 0}, {1, 1})), MeshClosure::Open);  // a quad
    Mesh holed = makeCube({0, 0, 0}, 1.0f);
    holed.indices.resize(holed.indices.size() - 3);  // one triangle missing: three edges with one triangle
    EXPECT_EQ(meshClosure(holed), MeshClosure::Open);
    Mesh flipped = makeCube({0, 0, 0}, 1.0f);
    std::swap(flipped.indices[1], flipped.indices[2]);  // one triangle turned against its neighbours
    EXPECT_EQ(meshClosure(flipped), MeshClosure::Open);
    const Mesh cube = makeCube({0, 0, 0}, 1.0f);
    EXPECT_EQ(meshClosure(merged(cube, cube)), MeshClosure::Open);  // every edge with four triangles
    EXPECT_EQ(meshClosure(Mesh{}), MeshClosure::Open);
}

TEST(MeshTopology, InsideOutMeshesAndMixedOrientations) {
    EXPECT_EQ(meshClosure(reversed(makeCube({0, 0, 0}, 1.0f))), MeshClosure::ClosedInward);
    EXPECT_EQ(meshClosure(merged(makeCube({0, 0, 0}, 1.0f), makeCube({3, 0, 0}, 1.0f))), MeshClosure::ClosedOutward);
    // Two solids, one inside out: no one face to cull serves both.
    EXPECT_EQ(meshClosure(merged(makeCube({0, 0, 0}, 1.0f), reversed(makeCube({3, 0, 0}, 1.0f)))), MeshClosure::Open);
    // A quad and its reverse: closed edges, but it encloses nothing (both sides are seen).
    const Mesh quad = makePlane({0, 0, 0}, {0, 0, 1}, {1, 1});
    EXPECT_EQ(meshClosure(merged(quad, reversed(quad))), MeshClosure::Open);
}

TEST(MeshTopology, WeldingJoinsEqualPositionsOnly) {
    Mesh mesh;
    for (const glm::vec3 p : {glm::vec3(0, 0, 0), glm::vec3(1, 0, 0), glm::vec3(-0.0f, 0, 0), glm::vec3(1e-7f, 0, 0),
                              glm::vec3(1, 0, 0)})
        mesh.vertices.push_back({p, {0, 0, 1}, {0, 0}, {1, 0, 0}});
    EXPECT_EQ(weldPositions(mesh), (std::vector<uint32_t>{0, 1, 0, 3, 1}));
}

// The seams of the procedural shapes are exact: a seam 10⁻⁷ apart would leave the sphere open.
TEST(MeshTopology, ProceduralSeamsShareTheirPositions) {
    const Mesh sphere = makeUvSphere({0, 0, 0}, 1.0f, 16, 8);
    const std::vector<uint32_t> welded = weldPositions(sphere);
    for (int ring = 0; ring <= 8; ++ring) EXPECT_EQ(welded[ring * 17 + 16], welded[ring * 17]) << "ring " << ring;
    for (int segment = 1; segment <= 16; ++segment) {
        EXPECT_EQ(welded[segment], welded[0]);            // the north pole
        EXPECT_EQ(welded[8 * 17 + segment], welded[8 * 17]);  // the south pole
    }
}

TEST(Visibility, BackFacesAreCulledOnlyOnClosedMeshesSeenFromOutside) {
    EXPECT_EQ(culledFaces(MeshClosure::ClosedOutward, true), CulledFaces::Back);
    EXPECT_EQ(culledFaces(MeshClosure::ClosedInward, true), CulledFaces::Front);
    EXPECT_EQ(culledFaces(MeshClosure::Open, true), CulledFaces::None);
    EXPECT_EQ(culledFaces(MeshClosure::ClosedOutward, false), CulledFaces::None);

    Camera camera;  // at (0, 0, 4) looking at the origin, near plane 0.05
    EXPECT_TRUE(beyondNearPlane(camera, {{0, 0, 0}, 1.0f}));
    EXPECT_FALSE(beyondNearPlane(camera, {{0, 0, 0}, 5.0f}));    // the camera is inside
    EXPECT_FALSE(beyondNearPlane(camera, {{0, 0, 3.5f}, 0.5f}));  // the near plane cuts it
    EXPECT_FALSE(beyondNearPlane(camera, {{0, 0, 6}, 1.0f}));     // behind the camera
}

TEST(Visibility, ShadowMapsCullOnlyWhenTheLightIsOutside) {
    const BoundingSphere object{{0, 0, 0}, 1.0f}, scene{{0, 0, 0}, 3.0f};
    Light sun;
    sun.type = LightType::Directional;
    sun.direction = {0, -1, 0};
    EXPECT_TRUE(beyondNearPlane(*shadowProjection(sun, scene), object));
    Light bulb;
    bulb.type = LightType::Point;
    bulb.position = {0, 2, 0};
    EXPECT_TRUE(beyondNearPlane(*shadowProjection(bulb, scene), object));
    bulb.position = {0, 0.5f, 0};  // inside the object
    EXPECT_FALSE(beyondNearPlane(*shadowProjection(bulb, scene), object));
    bulb.position = {0, 1.0f + 1e-5f, 0};  // closer than its near plane's corners
    EXPECT_FALSE(beyondNearPlane(*shadowProjection(bulb, scene), object));
}

TEST(Visibility, SpheresOutsideTheFrustumAreRejected) {
    Camera camera;  // 40° vertical field of view, far plane 100
    const glm::mat4 viewProjection = camera.viewProjection(1.0f);
    EXPECT_FALSE(outsideFrustum(viewProjection, {{0, 0, 0}, 1.0f}));
    EXPECT_TRUE(outsideFrustum(viewProjection, {{0, 0, 6}, 1.0f}));     // behind the camera
    EXPECT_TRUE(outsideFrustum(viewProjection, {{5, 0, 0}, 1.0f}));     // off to the side: tan 20° · 4 ≈ 1.5
    EXPECT_FALSE(outsideFrustum(viewProjection, {{2.2f, 0, 0}, 1.0f}));  // straddles the side plane
    EXPECT_TRUE(outsideFrustum(viewProjection, {{0, 0, -200}, 1.0f}));  // beyond the far plane
}

TEST(Visibility, CoveredPixelsBoundTheProjectedDisc) {
    Camera camera;  // at (0, 0, 4), 40° vertical field of view
    const double tangent = std::tan(glm::radians(20.0));
    // A small sphere 10 m away: a disc of radius 0.1 / ((10 − 0.1)·tan 20°) of half the height.
    const double radius = 0.1 / (9.9 * tangent) * 50.0;
    EXPECT_NEAR(coveredPixels(camera, {{0, 0, -6}, 0.1f}, 100, 100), 3.14159265358979 * radius * radius, 1e-3);
    EXPECT_EQ(coveredPixels(camera, {{0, 0, 0}, 3.0f}, 100, 100), 100.0 * 100.0);  // fills the image
    EXPECT_EQ(coveredPixels(camera, {{0, 0, 4}, 1.0f}, 64, 48), 64.0 * 48.0);     // the camera is inside
    camera.projection = Projection::Orthographic;  // 2.5 m high
    EXPECT_NEAR(coveredPixels(camera, {{0, 0, 0}, 0.25f}, 100, 100), 3.14159265358979 * 10.0 * 10.0, 1e-3);
}

// Every point of the sphere projects into its covered rectangle, which is tight: a pixel's margin
// beyond the outline, in perspective from several directions and orthographic.
TEST(Visibility, CoveredRectHoldsTheSphereAndLittleElse) {
    Camera camera;  // at (0, 0, 4) looking at the origin, 40° vertical field of view
    const int width = 160, height = 120;
    for (Projection projection : {Projection::Perspective, Projection::Orthographic})
        for (const BoundingSphere sphere : {BoundingSphere{{0, 0, 0}, 1.0f}, BoundingSphere{{1.3f, -0.7f, 1.0f}, 0.4f},
                                            BoundingSphere{{-2.0f, 1.0f, -3.0f}, 1.5f}}) {
            camera.projection = projection;
            const PixelRegion rect = coveredRect(camera, sphere, width, height);
            const glm::mat4 viewProjection = camera.viewProjection(static_cast<float>(width) / height);
            glm::vec2 low(1e9f), high(-1e9f);
            for (int i = 0; i < 64; ++i)
                for (int j = 0; j <= 32; ++j) {
                    const float phi = 2.0f * 3.14159265f * i / 64, theta = 3.14159265f * j / 32;
                    const glm::vec3 point = sphere.center + sphere.radius * glm::vec3(std::sin(theta) * std::cos(phi),
                                                                                      std::cos(theta), std::sin(theta) * std::sin(phi));
                    const glm::vec4 clip = viewProjection * glm::vec4(point, 1.0f);
                    const glm::vec2 pixel = (glm::vec2(clip) / clip.w * 0.5f + 0.5f) * glm::vec2(width, height);
                    low = glm::min(low, pixel), high = glm::max(high, pixel);
                }
            EXPECT_LE(rect.x, std::max(0.0f, low.x));
            EXPECT_LE(rect.y, std::max(0.0f, low.y));
            EXPECT_GE(rect.x + rect.width, std::min<float>(width, high.x));
            EXPECT_GE(rect.y + rect.height, std::min<float>(height, high.y));
            EXPECT_GE(rect.x, low.x - 3.0f);  // the outline sampled at 64 meridians: a pixel's margin and a little
            EXPECT_LE(rect.x + rect.width, high.x + 3.0f);
        }
    camera.projection = Projection::Perspective;
    const PixelRegion around = coveredRect(camera, {{0, 0, 4.5f}, 1.0f}, width, height);  // holds the eye
    EXPECT_EQ(around.width * around.height, width * height);
    const PixelRegion behind = coveredRect(camera, {{0, 0, 5.5f}, 1.0f}, width, height);  // behind the eye
    EXPECT_EQ(behind.width * behind.height, width * height);
}

}  // namespace
}  // namespace glint
