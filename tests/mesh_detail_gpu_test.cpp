// Large meshes on the GPU (gl/gpu_mesh_cache.h): the simplified stand-in is drawn only when a
// render asks for it and once it is made, looks like the full mesh, and shadow maps drawn from
// stand-ins are drawn again for the next full-detail frame (and only then).
#include <gtest/gtest.h>

#include <cmath>

#include "gpu_test_support.h"

namespace glint {
namespace {

constexpr int kSize = 64;
// A sphere of 350 × 300 segments and rings: 209,300 triangles, just above the size that gets a
// stand-in (kSimplifyAboveTriangles).
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

RadianceImage render(const Scene& scene, MeshDetail detail) {
    Renderer& renderer = test::sharedHeadless().renderer();
    const Status status = renderer.renderRadiance(scene, kSize, kSize, detail);
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
    EXPECT_LE(renderer.trianglesDrawn(), static_cast<long long>(kSimplifiedTriangles) + 2);
    EXPECT_GE(renderer.trianglesDrawn(), static_cast<long long>(kSimplifiedTriangles) / 2);
    // Differences only along the silhouette and in the shading of a few cells.
    EXPECT_LT(meanAbsoluteDifference(full, simplified), 0.01 * mean(full));
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
    scene.materials[0].values[0] = 0.3f;  // a material drag keeps the full-detail maps
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

}  // namespace
}  // namespace glint
