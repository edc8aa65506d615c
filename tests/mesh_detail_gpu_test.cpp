// Large meshes on the GPU (gl/gpu_mesh_cache.h): simplified stand-ins are drawn only when a
// render asks for them and once they are made, at the level of detail the covered pixels call
// for, and look like the full mesh; shadow maps drawn from stand-ins are drawn again for the next
// full-detail frame (and only then), as are maps a drag frame drew coarser.
#include <gtest/gtest.h>

#include <cmath>

#include "gpu_test_support.h"

namespace glint {
namespace {

constexpr int kSize = 64;
// A sphere of 350 × 300 segments and rings: 209,300 triangles, which gets all three stand-ins.
constexpr int kSegments = 350, kRings = 300;
constexpr long long kFullTriangles = 2LL * kSegments * kRings - 2 * kSegments;

Scene largeSphereOnAFloor() {
    Scene scene;
    scene.camera.position = {0.0f, 1.2f, 3.0f};
    scene.camera.target = {0.0f, -0.2f, 0.0f};
    scene.materials = {Material::withDefaults("plastic", BrdfModel::BlinnPhong)};
    scene.objects.push_back({"ball", SphereShape{{0, 0, 0}, 1.0f, kSegments, kRings}, 0, SurfaceInterpolation::Phong});
    scene.objects.push_back({"floor", PlaneShape{{0, -1, 0}, {0, 1, 0}, {8, 8}}, 0});
    Light sun;
    sun.type = LightType::Directional;
    sun.direction = glm::normalize(glm::vec3(-0.3f, -1.0f, -0.4f));
    sun.irradiance = 2.0f;
    sun.castsShadows = true;
    scene.lights = {sun};
    return scene;
}

RadianceImage render(const Scene& scene, MeshDetail detail, int size = kSize) {
    Renderer& renderer = test::sharedHeadless().renderer();
    const Status status = renderer.renderRadiance(scene, size, size, detail);
    EXPECT_TRUE(status.ok()) << status.error().format();
    return renderer.readRadiance();
}

double meanAbsoluteDifference(const RadianceImage& a, const RadianceImage& b) {
    double sum = 0.0;
    for (size_t i = 0; i < a.pixels.size(); ++i) sum += std::abs(a.pixels[i] - b.pixels[i]);
    return sum / static_cast<double>(a.pixels.size());
}

double mean(const RadianceImage& image) {
    double sum = 0.0;
    for (float value : image.pixels) sum += value;
    return sum / static_cast<double>(image.pixels.size());
}

TEST(MeshDetailGpu, TheStandInIsDrawnOnlyWhenAskedForAndLooksLikeTheMesh) {
    Renderer& renderer = test::sharedHeadless().renderer();
    const Scene scene = largeSphereOnAFloor();
    const RadianceImage full = render(scene, MeshDetail::Full);
    EXPECT_EQ(renderer.trianglesDrawn(), kFullTriangles + 2);
    EXPECT_EQ(renderer.simplifiedMeshesDrawn(), 0);
    renderer.prepareSimplifiedMeshes(scene);
    renderer.finishSimplifiedMeshes();
    const RadianceImage simplified = render(scene, MeshDetail::Simplified);
    EXPECT_EQ(renderer.simplifiedMeshesDrawn(), 1);
    // The sphere covers at most 64² pixels: the coarsest stand-in, of at most 6,250 triangles.
    EXPECT_LE(renderer.trianglesDrawn(), static_cast<long long>(kSimplifiedTriangles[2]) + 2);
    EXPECT_GE(renderer.trianglesDrawn(), static_cast<long long>(kSimplifiedTriangles[2]) / 2);
    // Differences only along the silhouette and in the shading of a few cells.
    EXPECT_LT(meanAbsoluteDifference(full, simplified), 0.01 * mean(full));
    // At 256² it may cover all 65,536 pixels: the 25,000-triangle stand-in (the finest within).
    (void)render(scene, MeshDetail::Simplified, 256);
    EXPECT_LE(renderer.trianglesDrawn(), static_cast<long long>(kSimplifiedTriangles[1]) + 2);
    EXPECT_GT(renderer.trianglesDrawn(), static_cast<long long>(kSimplifiedTriangles[2]) + 2);
    (void)render(scene, MeshDetail::Full);
    EXPECT_EQ(renderer.trianglesDrawn(), kFullTriangles + 2);
    EXPECT_EQ(renderer.simplifiedMeshesDrawn(), 0);
}

TEST(MeshDetailGpu, ShadowMapsFromStandInsAreRedrawnForTheFullFrame) {
    Renderer& renderer = test::sharedHeadless().renderer();
    Scene scene = largeSphereOnAFloor();
    (void)render(scene, MeshDetail::Full);
    renderer.prepareSimplifiedMeshes(scene);
    renderer.finishSimplifiedMeshes();
    const long long first = renderer.shadowMapRenders();
    scene.materials[0].analytic()->values[0] = 0.3f;  // a material drag keeps the full-detail maps
    (void)render(scene, MeshDetail::Simplified);
    EXPECT_EQ(renderer.shadowMapRenders(), first);
    scene.lights[0].direction.x += 0.05f;  // a light drag draws them from the stand-in
    (void)render(scene, MeshDetail::Simplified);
    EXPECT_EQ(renderer.shadowMapRenders(), first + 1);
    (void)render(scene, MeshDetail::Simplified);
    EXPECT_EQ(renderer.shadowMapRenders(), first + 1);
    (void)render(scene, MeshDetail::Full);  // the drag ended: every triangle again
    EXPECT_EQ(renderer.shadowMapRenders(), first + 2);
    (void)render(scene, MeshDetail::Full);
    EXPECT_EQ(renderer.shadowMapRenders(), first + 2);
}

// Without any large mesh, a drag frame still draws a changed map coarser (about two texels per
// pixel of its 64-pixel side: 256² instead of 1024²), and the full frame draws it again.
TEST(MeshDetailGpu, ADragFramesMapsAreCoarserAndDrawnAgainAfter) {
    Renderer& renderer = test::sharedHeadless().renderer();
    Scene scene = defaultScene();
    scene.lights[0].castsShadows = true;
    const RadianceImage before = render(scene, MeshDetail::Full);
    const long long first = renderer.shadowMapsDrawn();
    scene.lights[0].direction.x += 0.02f;
    const RadianceImage dragged = render(scene, MeshDetail::Simplified);
    EXPECT_EQ(renderer.shadowMapsDrawn(), first + 1);
    EXPECT_EQ(renderer.simplifiedMeshesDrawn(), 0);
    const RadianceImage full = render(scene, MeshDetail::Full);
    EXPECT_EQ(renderer.shadowMapsDrawn(), first + 2);
    (void)render(scene, MeshDetail::Full);
    EXPECT_EQ(renderer.shadowMapsDrawn(), first + 2);
    EXPECT_GT(meanAbsoluteDifference(dragged, full), 0.0);  // the coarser map shows at the shadow's edge
    EXPECT_LT(meanAbsoluteDifference(dragged, full), 0.05 * mean(full));
    EXPECT_GT(meanAbsoluteDifference(before, full), 0.0);
}

}  // namespace
}  // namespace glint
